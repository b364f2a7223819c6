"""Paper 000's snapshots of the contact network under ultrasound (Figs. 10,
12 and 13): the frames of a snapshot job (avalanche_study.snapshot_settings:
a layer tilted at rest to 15 deg, then the drive switched on, one frame per
ms) at the times the paper shows, cut to a window of the layer's middle and
kept in the record as small JSON files, then read back by the figures.

  frame_times       the time (ms) of each frame since the first
  crop              the grains of a window and the contacts between them
  snapshot          one frame of a job as the record keeps it (a dict)
  job_frames        the snapshots of a finished job at its times, from its dumps
  write_snapshots   snapshot_<t>ms.json of a finished job into its record
  read_snapshots    the snapshots of a job (record or production), by time
  snapshot_numbers  where the friction drops and how the response decays (the tables)

A snapshot holds the grains (id, type, x, y, radius, and qx, qy: U0 q of
fix acoustic/mindlin, signed, in m) and their contacts (i, j, f_n, k_n,
U_t, mu*/mu: the fix's local array), with U0 in m to normalise q.
"""
import glob
import json
import os

import numpy as np

from . import avalanche as av
from .lammps_output import read_dump

D = 7e-4                 # m: in.material's mean diameter d (U0 is set in d)
WINDOW = 30.0            # d: the width of the layer's middle that a snapshot keeps
GRAIN_COLUMNS = ("id", "type", "x", "y", "radius", "qx", "qy")
Q_COLUMNS = ("f_us[1]", "f_us[2]")     # in.avalanche's dumpq columns: U0 q_x, U0 q_y


def frame_times(frames):
    """The time of each frame since the first, in ms (in.avalanche's tchunk,
    1 ms, is the dump interval of a snapshot job: dumpevery 1)."""
    steps = np.array([f.timestep for f in frames], dtype=float)
    if len(steps) < 2:
        return np.zeros(len(steps))
    per_ms = steps[1] - steps[0]
    return (steps - steps[0]) / per_ms


def crop(atoms, contacts, width_d=WINDOW, d=D):
    """The grains within width_d diameters of the middle of the layer (the
    mean of the extreme x of the type-1 grains) and the contacts with both
    ends among them (a wall contact, j = 0, with its grain): (grains dict,
    contacts dict, (x0, x1))."""
    grains = atoms["type"] == 1
    middle = 0.5 * (atoms["x"][grains].min() + atoms["x"][grains].max())
    x0, x1 = middle - 0.5 * width_d * d, middle + 0.5 * width_d * d
    inside = (atoms["x"] >= x0) & (atoms["x"] <= x1)
    kept = {int(t) for t in atoms["id"][inside]}
    c = av.contact_columns(contacts)
    rows = np.array([int(i) in kept and (int(j) in kept or int(j) == 0) for i, j in zip(c["i"], c["j"])], bool)
    names = dict(zip(GRAIN_COLUMNS, ("id", "type", "x", "y", "radius") + Q_COLUMNS))
    grain_data = {name: atoms[column][inside].tolist() for name, column in names.items()}
    contact_data = {name: c[name][rows].tolist() for name in av.CONTACT_COLUMNS}
    return grain_data, contact_data, (x0, x1)


def snapshot(atoms, contacts, t_ms, settings, width_d=WINDOW, d=D):
    """One frame of a snapshot job as the record keeps it."""
    grains, pairs, window = crop(atoms, contacts, width_d, d)
    return {"job": settings.get("tag"), "H": settings["H"], "seed": settings["seed"], "freq": settings["freq"],
            "kappa": settings["kappa"], "U0": settings["U0"] * d, "U0_over_d": settings["U0"], "d": d,
            "theta": float(atoms["v_th"][0]), "t_ms": t_ms, "timestep": atoms.timestep, "window": list(window),
            "grains": grains, "contacts": pairs}


def job_frames(directory, settings, width_d=WINDOW):
    """{t: snapshot} at the times (ms) of settings["snapshots"], from the
    dump and contacts of the snapshot job in directory."""
    tag = settings["tag"]
    frames = read_dump(os.path.join(directory, f"{tag}.dump"))
    contacts = {c.timestep: c for c in read_dump(os.path.join(directory, f"{tag}.contacts"))}
    times = frame_times(frames)
    out = {}
    for t in settings["snapshots"]:
        k = int(np.argmin(np.abs(times - t)))
        if abs(times[k] - t) > 0.5:
            raise ValueError(f"{directory}: no frame at {t} ms (frames up to {times[-1]:g} ms)")
        frame = frames[k]
        if frame.timestep not in contacts:
            raise ValueError(f"{directory}: no contacts at timestep {frame.timestep}")
        out[int(t)] = snapshot(frame, contacts[frame.timestep], float(times[k]), settings, width_d)
    return out


def write_snapshots(directory, settings, dest, width_d=WINDOW):
    """snapshot_<t>ms.json in dest for each time t (ms) of settings["snapshots"]
    (job_frames); returns the paths written."""
    written = []
    for t, snap in job_frames(directory, settings, width_d).items():
        path = os.path.join(dest, f"snapshot_{t}ms.json")
        with open(path, "w") as handle:
            json.dump(snap, handle)
            handle.write("\n")
        written.append(path)
    return written


def _arrays(snap):
    for part in ("grains", "contacts"):
        snap[part] = {name: np.asarray(values) for name, values in snap[part].items()}
    return snap


def read_snapshots(directory, settings=None):
    """{t_ms: snapshot} of a snapshot job, the columns as numpy arrays: its
    snapshot_*ms.json (a recorded job), else with settings from its dumps
    (a job of the production)."""
    paths = sorted(glob.glob(os.path.join(directory, "snapshot_*ms.json")))
    if not paths and settings is not None and os.path.exists(os.path.join(directory, f"{settings['tag']}.dump")):
        return {t: _arrays(snap) for t, snap in job_frames(directory, settings).items()}
    out = {}
    for path in paths:
        with open(path) as handle:
            snap = _arrays(json.load(handle))
        out[int(round(snap["t_ms"]))] = snap
    return out


def snapshot_numbers(snap, bottom=3.0, top=6.0, bands=4, band=2.0):
    """What a snapshot says in numbers: (contacts between two grains,
    fraction of them with mu*/mu < 0.5 over the window, among those whose
    middle lies within `bottom` d of the base's top, and above `top` d;
    median |q|/U0 of the grains in `bands` bands of `band` d from the
    base's top up)."""
    g, c, d = snap["grains"], snap["contacts"], snap["d"]
    base = g["type"] != 1
    y_base = g["y"][base].max() if base.any() else g["y"].min()
    row = {int(t): k for k, t in enumerate(g["id"])}
    pairs = [k for k, (i, j) in enumerate(zip(c["i"], c["j"])) if int(i) in row and int(j) in row]
    height = np.array([0.5 * (g["y"][row[int(c["i"][k])]] + g["y"][row[int(c["j"][k])]]) for k in pairs]) - y_base
    reduced = np.asarray(c["mu_ratio"])[pairs] < 0.5
    height = height / d

    def share(mask):
        return float(np.mean(reduced[mask])) if mask.any() else float("nan")

    q = np.hypot(g["qx"], g["qy"]) / snap["U0"]
    h = (g["y"] - y_base) / d
    medians = []
    for k in range(bands):
        inside = (~base) & (h >= k * band) & (h < (k + 1) * band)
        medians.append(float(np.median(q[inside])) if inside.any() else float("nan"))
    return len(pairs), share(np.ones(len(pairs), bool)), share(height < bottom), share(height > top), medians
