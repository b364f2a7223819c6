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
the base) / t10.  Runs through LAMMPS's Python module
(acoustic_tools.avalanche_calibration); writes a JSON file, which
`python3 -m acoustic_tools.avalanche_figures calibration` draws.

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

from acoustic_tools.avalanche_calibration import SCANS, SOURCES, calibration_scan

HERE = os.path.dirname(os.path.abspath(__file__))


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
    results = calibration_scan(os.path.abspath(args.restart), os.path.join(HERE, "in.material"), args.freq, scans,
                               args.sources, spectrum=not args.no_spectrum)
    with open(args.output, "w") as handle:
        json.dump(results, handle, indent=1)


if __name__ == "__main__":
    main()
