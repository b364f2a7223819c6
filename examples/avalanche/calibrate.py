"""Calibration scan of the vibration model on a frozen layer (no ramp): how
the friction reduction, the place of 70 kHz in the spectrum and the layer's
sound speed depend on U0/d, kappa_scale, C_mu and the damping ratio, for two
sources of the basal vibration:

  bottom  paper 000's Eq. 2.11: the grains touching the base (its set J)
          move normally to the base with amplitude U0 (mode normal), free
          along it; the base grains are not in the network, so the contacts
          with the base keep their friction;
  base    the rough base of frozen grains vibrates as a whole (every
          translation prescribed) and its contacts are in the network: the
          source of examples/avalanche/in.avalanche so far.

One parameter at a time moves away from the reference (U0/d 1e-5, kappa_scale
0.3, C_mu 1, damping 0); each set is one update of fix acoustic/mindlin (run
0) on the layer of the restart file.  For each kappa_scale also: the
eigenfrequencies (compute vibration/modes, base clamped) and the time of
flight of a pulse from the base to the grains of the top diameter (compute
vibration/pulse, 10 % arrival), whose speed is (height of the detector above
the base) / t10.  Runs through LAMMPS's Python module; writes a JSON file,
and a PNG with tools/avalanche_figures.py.

  PYTHONPATH=build/lammps-tree/python:tools LD_LIBRARY_PATH=build/lammps \\
    /usr/bin/python3 examples/avalanche/calibrate.py out/demo/deposit.restart out/calibration.json

One scan of a large layer (the dense modes of the spectrum grow as the cube
of the grains; in.modes -var method kpm gives its band instead):

    ... calibrate.py STATE.restart out.json --scan kappa --values 0.15 0.17 0.2 0.3 \\
        --sources bottom --no-spectrum
"""
import argparse
import json
import os
import sys

import numpy as np
from lammps import lammps, LMP_STYLE_GLOBAL, LMP_STYLE_LOCAL, LMP_TYPE_ARRAY, LMP_TYPE_VECTOR

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
import sound  # noqa: E402

REFERENCE = {"U0": 1e-5, "kappa": 0.3, "cmu": 1.0, "zeta": 0.0}
SCANS = {"U0": [1e-6, 3e-6, 1e-5, 3e-5, 1e-4, 3e-4, 1e-3],
         "kappa": [0.01, 0.03, 0.1, 0.3, 1.0],
         "cmu": [0.3, 1.0, 3.0],
         "zeta": [0.0, 0.01, 0.05]}
SOURCES = ("bottom", "base")


def open_layer(restart):
    """LAMMPS with the frozen layer, the groups J (grains touching the base)
    and top (grains within one diameter of the highest grain centre)"""
    lmp = lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    lmp.commands_string(f"""
include         {HERE}/in.material
read_restart    {restart}
comm_modify     vel yes
neighbor        $(0.2*v_d) bin
timestep        ${{dt}}
compute         touch grains contact/atom base
compute         ntouch grains reduce sum c_touch
thermo_style    custom step c_ntouch
run             0 post no
variable        onbase atom c_touch>0
group           J variable onbase
variable        ytop equal bound(grains,ymax)
variable        attop atom (type==1)*(y>v_ytop-v_d)
group           top variable attop
variable        nJ equal count(J)
""")
    return lmp


def layer_geometry(lmp):
    tags = lmp.numpy.extract_atom("id").copy()
    y = lmp.numpy.extract_atom("x")[:, 1].copy()
    types = lmp.numpy.extract_atom("type").copy()
    nlocal = lmp.extract_global("nlocal")
    tags, y, types = tags[:nlocal], y[:nlocal], types[:nlocal]
    base_top = y[types == 2].max()
    grains = y[types == 1]
    height = grains.max() - base_top
    detector = grains[grains > grains.max() - lmp.extract_variable("d")].mean() - base_top
    return ({int(t): float(v) for t, v in zip(tags, y)}, {int(t) for t in tags[types == 2]}, base_top, height,
            detector)


def friction_update(lmp, source, freq, U0, kappa, cmu, zeta, d, where):
    """one update of fix acoustic/mindlin; the global statistics and where
    the contacts with mu*/mu < 0.5 sit (thirds of the layer height, and the
    share of contacts with the base)"""
    y_of, base_tags, base_top, height, _ = where
    if source == "bottom":
        drive = "grains acoustic/mindlin 1 frequency {f} amplitude {a} source J mode normal direction 0 1 0"
    else:
        drive = "all acoustic/mindlin 1 frequency {f} amplitude {a} source base direction 0 1 0"
    lmp.commands_string(f"""
fix             us {drive.format(f=freq, a=U0 * d)} stiffness hertz ${{Eglass}} ${{nuglass}} &
                kappa_scale {kappa} cmu {cmu} damping {zeta}
run             0 post no
""")
    vector = [lmp.extract_fix("us", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR, k) for k in range(4)]
    local = np.array(lmp.numpy.extract_fix("us", LMP_STYLE_LOCAL, LMP_TYPE_ARRAY), dtype=float).reshape(-1, 6)
    lmp.command("unfix us")
    lowered = local[local[:, 5] < 0.5]
    heights = np.array([(y_of[int(i)] + y_of[int(j)]) / 2.0 - base_top for i, j in lowered[:, :2]])
    with_base = np.array([int(i) in base_tags or int(j) in base_tags for i, j in lowered[:, :2]])
    thirds = [float(np.mean((heights >= k * height / 3.0) & (heights < (k + 1) * height / 3.0)))
              if len(heights) else 0.0 for k in range(3)]
    return {"contacts": vector[0], "mean_factor": vector[1], "smallest_factor": vector[2],
            "fraction_below_half": vector[3],
            "lowered_in_thirds": thirds,
            "lowered_with_base": float(with_base.mean()) if len(with_base) else 0.0}


def spectrum_and_speed(lmp, kappa, freq, where):
    """eigenfrequencies of the network (base clamped) and the time-of-flight
    speed of a pulse from the base to the top grains"""
    detector = where[4]
    network = f"stiffness hertz ${{Eglass}} ${{nuglass}} kappa_scale {kappa}"
    lmp.commands_string(f"""
compute         modes all vibration/modes {network} fixed base method dense
compute         pulse all vibration/pulse source base detector top duration 2e-4 samples 4001 &
                method modes {network}
run             0 post no
""")
    frequencies = np.array(lmp.numpy.extract_compute("modes", LMP_STYLE_LOCAL, LMP_TYPE_ARRAY))[:, 1]
    signal = np.array(lmp.numpy.extract_compute("pulse", LMP_STYLE_GLOBAL, LMP_TYPE_ARRAY))
    lmp.commands_string("uncompute modes\nuncompute pulse")
    peak = sound.coherent_peak(signal[:, 0], signal[:, 1])
    positive = frequencies[frequencies > 0.0]
    return {"highest_mode": float(frequencies.max()),
            "modes_below_drive": float(np.mean(positive < freq)),
            "t10": float(peak["t10"]), "t_peak": float(peak["t_peak"]), "detector_height": float(detector),
            "speed": float(detector / peak["t10"])}


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("restart")
    parser.add_argument("output")
    parser.add_argument("--freq", type=float, default=70e3)
    parser.add_argument("--quick", action="store_true", help="two values per scan (tests)")
    parser.add_argument("--scan", choices=sorted(SCANS), help="this parameter only")
    parser.add_argument("--values", type=float, nargs="+", help="its values (with --scan)")
    parser.add_argument("--sources", choices=SOURCES, nargs="+", default=list(SOURCES))
    parser.add_argument("--no-spectrum", action="store_true",
                        help="no eigenmodes and pulse (dense: too costly for thousands of grains)")
    args = parser.parse_args(argv)
    if args.values and not args.scan:
        parser.error("--values needs --scan")
    scans = {k: (v[::len(v) - 1] if args.quick else v) for k, v in SCANS.items()
             if args.scan in (None, k)}
    if args.values:
        scans[args.scan] = args.values
    lmp = open_layer(os.path.abspath(args.restart))
    d = lmp.extract_variable("d")
    where = layer_geometry(lmp)
    results = {"reference": REFERENCE, "freq": args.freq, "grains": int(lmp.get_natoms()),
               "J": int(lmp.extract_variable("nJ")), "height": where[3], "scans": {}}
    for source in args.sources:
        for name, values in scans.items():
            rows = []
            for value in values:
                p = dict(REFERENCE, **{name: value})
                row = friction_update(lmp, source, args.freq, p["U0"], p["kappa"], p["cmu"], p["zeta"], d, where)
                row["value"] = value
                rows.append(row)
            results["scans"][f"{source}:{name}"] = rows
    speeds = []
    for kappa in ([] if args.no_spectrum else scans.get("kappa", [])):
        row = spectrum_and_speed(lmp, kappa, args.freq, where)
        row["kappa"] = kappa
        speeds.append(row)
    results["spectrum_and_speed"] = speeds
    lmp.close()
    with open(args.output, "w") as handle:
        json.dump(results, handle, indent=1)


if __name__ == "__main__":
    main()
