"""The motion of a layer at one angle, as paper 000's Figs. 6, 9 and 14 show
it: the grains' speed over the observation window at times since the tilt
(0 to 1.2 s), the speed along the whole layer (is the flow led by the
front?) and sigma_1, sigma_2 against time, reduced from a ramp's or t_con
run's dump and series to a small JSON file that the record keeps
(fields.json; the dumps are not kept).

  speed_cells     mean speed of the grains in cells of the observation window
  column_speeds   mean speed of the grains in columns along the whole layer
  angle_fields    both at the frames of one angle, with the sigma_l series
  job_fields      the angles of a finished job that the figures need
  write_fields    fields.json of a finished job into its record
  read_fields     fields.json back (as_array: one of its lists as an array)

Times are in s since the tilt to the angle (in.avalanche's `time` is the
timestep times dt from the deposit on, so a frame's time is its timestep
times the run's dt); lengths in d; speeds in m/s.
"""
import json
import os

import numpy as np

from . import avalanche as av
from .lammps_output import read_dump

CELL = (4.0, 2.0)        # d: the cells of the window (along, across the slope)
COLUMN = 10.0            # d: the columns along the whole layer
TIMES = tuple(round(0.2 * k, 1) for k in range(7))   # s: paper 000's 7 snapshots over 1.2 s
SIGMA_EVERY = 5          # ms between the sigma_l samples kept
FIELDS = "fields.json"
FRAME_TOLERANCE = 0.051  # s: a kept time takes the nearest frame this close (the ramps' frames: every 50 ms)


def _base_top(frame):
    grains = frame["type"] == 1
    return frame["y"][~grains].max() if np.any(~grains) else frame["y"].min()


def _mean_in(bins_x, bins_y, values, nx, ny):
    total = np.zeros((ny, nx))
    count = np.zeros((ny, nx))
    np.add.at(total, (bins_y, bins_x), values)
    np.add.at(count, (bins_y, bins_x), 1)
    with np.errstate(invalid="ignore"):
        return np.where(count > 0, total / np.maximum(count, 1), np.nan)


def speed_cells(frame, window, d, height_d, cell=CELL):
    """Mean speed |v| (m/s) of the grains (type 1) in cells of cell[0] x
    cell[1] d of the window (x0, x1) (m), from the base's top up to height_d
    d: an array (rows from the base up, columns along the slope), nan where
    a cell holds no grain."""
    x0, x1 = window
    nx = max(1, int(round((x1 - x0) / (cell[0] * d))))
    ny = max(1, int(np.ceil(height_d / cell[1])))
    grains = (frame["type"] == 1) & (frame["x"] >= x0) & (frame["x"] < x1)
    ix = np.clip(((frame["x"][grains] - x0) / (cell[0] * d)).astype(int), 0, nx - 1)
    iy = np.clip(((frame["y"][grains] - _base_top(frame)) / (cell[1] * d)).astype(int), 0, ny - 1)
    speed = np.hypot(frame["vx"][grains], frame["vy"][grains])
    return _mean_in(ix, iy, speed, nx, ny)


def column_speeds(frame, d, column=COLUMN):
    """(x of the columns' left ends (m), mean speed (m/s) of the grains in
    each column of `column` d) along the whole layer, from its back (the
    smallest x of a grain) to its front."""
    grains = frame["type"] == 1
    x = frame["x"][grains]
    lo = x.min()
    n = max(1, int(np.ceil((x.max() - lo) / (column * d) - 1e-9)))
    ix = np.clip(((x - lo) / (column * d)).astype(int), 0, n - 1)
    speed = np.hypot(frame["vx"][grains], frame["vy"][grains])
    return lo + column * d * np.arange(n), _mean_in(ix, np.zeros(len(ix), int), speed, n, 1)[0]


def angle_fields(frames, series, theta, dt, obs, times=TIMES):
    """The motion at angle theta: the frames at that angle nearest to each of
    `times` (s since the tilt; those the angle lasted), their speed cells
    over the observation window obs (fractions of the box), their column
    speeds, and sigma_1, sigma_2 and the mobile fraction of the observed
    grains every SIGMA_EVERY ms; a dict (JSON values,
    nan as None)."""
    parts = [(t, idx) for th, t, idx in av.angle_samples(series) if abs(th - theta) < 1e-6]
    if not parts:
        raise ValueError(f"no series samples at {theta:g} deg")
    t_since, idx = parts[-1]
    t0 = series["time"][idx[0]] - t_since[0]
    at = [f for f in frames if len(f) and abs(float(f["v_th"][0]) - theta) < 1e-6
          and f.timestep * dt >= t0 - 0.5 * dt]
    d = 2.0 * np.mean(frames[0]["radius"][frames[0]["type"] == 1])
    lo, hi = frames[0].box[0]
    window = (lo + obs[0] * (hi - lo), lo + obs[1] * (hi - lo))
    grains = frames[0]["type"] == 1
    height = (frames[0]["y"][grains] + frames[0]["radius"][grains]).max() - _base_top(frames[0])
    snapshots = []
    if at:
        frame_t = np.array([f.timestep * dt - t0 for f in at])
        for t in times:
            k = int(np.argmin(np.abs(frame_t - t)))
            if abs(frame_t[k] - t) > FRAME_TOLERANCE or any(s["t"] == round(float(frame_t[k]), 3) for s in snapshots):
                continue
            x, columns = column_speeds(at[k], d)
            snapshots.append({"t": round(float(frame_t[k]), 3),
                              "speed": _json(speed_cells(at[k], window, d, height / d)),
                              "column_x": [round(float(v / d), 2) for v in x], "columns": _json(columns)})
    keep = slice(SIGMA_EVERY - 1, None, SIGMA_EVERY)
    return {"theta": float(theta), "t_end": round(float(t_since[-1]), 3), "d": float(d),
            "window_d": [round(float((w - lo) / d), 2) for w in window], "cell_d": list(CELL),
            "height_d": round(float(height / d), 2), "snapshots": snapshots,
            "sigma_t": [round(float(v), 4) for v in t_since[keep]],
            "sigma1": _json(series["sigma1"][idx][keep]), "sigma2": _json(series["sigma2"][idx][keep]),
            "mobile": _json(series["mobile"][idx][keep])}


def _json(values):
    """An array as nested lists of numbers to 4 significant digits, None where nan."""
    array = np.asarray(values, dtype=float)
    if array.ndim > 1:
        return [_json(row) for row in array]
    return [float(f"{v:.4g}") if np.isfinite(v) else None for v in array]


def as_array(values):
    """A list of fields.json back as a float array, nan where None."""
    return np.array([[np.nan if v is None else v for v in row] for row in values] if values and
                    isinstance(values[0], list) else [np.nan if v is None else v for v in values], dtype=float)


def job_angles(settings, result, before=3):
    """The angles of a finished job whose motion the figures show: a t_con
    run's one angle; for a ramp theta_m (or its last angle) and the `before`
    angles under it that were followed (something moved)."""
    angles = result.get("angles", [])
    if settings.get("kind") == "tcon" or not angles:
        return [float(a["theta"]) for a in angles]
    last = [k for k, a in enumerate(angles) if a["state"] == "uniform"]
    end = last[0] if last else len(angles) - 1
    followed = [float(a["theta"]) for a in angles[:end] if float(a["time"]) > 0.1 + 1e-6]
    return followed[-before:] + [float(angles[end]["theta"])]


def job_fields(directory, settings, result, obs):
    """The fields of the angles of job_angles from the dump and series of a
    finished job in directory (None without a dump): a dict."""
    tag = settings["tag"]
    dump = os.path.join(directory, f"{tag}.dump")
    if not os.path.exists(dump):
        return None
    frames = read_dump(dump)
    series = av.read_series(os.path.join(directory, f"{tag}.series"))
    return {"job": os.path.basename(directory), "H": settings["H"], "seed": settings["seed"],
            "freq": settings["freq"], "kappa": settings.get("kappa"), "theta_m": result.get("theta_m"),
            "angles": [angle_fields(frames, series, theta, float(result["dt"]), obs)
                       for theta in job_angles(settings, result)]}


def write_fields(directory, settings, result, dest, obs):
    """dest/fields.json of a finished job (job_fields); its path, or None
    when the job has no dump."""
    fields = job_fields(directory, settings, result, obs)
    if fields is None:
        return None
    path = os.path.join(dest, FIELDS)
    with open(path, "w") as handle:
        json.dump(fields, handle, separators=(",", ":"))
        handle.write("\n")
    return path


def read_fields(directory):
    """The fields.json of a recorded job, or None."""
    path = os.path.join(directory, FIELDS)
    if not os.path.exists(path):
        return None
    with open(path) as handle:
        return json.load(handle)
