"""Acceptance checks of one paper-003 packing, beside the paper's Table I.

Called by examples/sound/in.packing through LAMMPS's `shell` command once
the packing is at rest, on the dumps it has just written:

  /usr/bin/python3 -m acoustic_tools.packing_checks DIR P W H D SIGMA_RATIO

DIR holds grains.dump (id x y z radius mass) and contacts.dump (fix
acoustic/mindlin's local array: i, j (0 for a wall), f_n, k_n); P the target
pressure, W the width, H the height of the piston, D the depth (0: 2D),
SIGMA_RATIO the bulk sigma11/sigma22 of LAMMPS's contact virial.  Writes
DIR/checks.lmp, which the deck includes: print commands that put the checks
into its log, and the string variable `checks`, the checks as one JSON
object, which in.sound writes into the sample's result.json.
"""
import json
import os
import sys

from . import lammps_output, sound


def packing_checks(directory, pressure, width, height, depth, sigma_ratio):
    """Table I's quantities of the packing in `directory` and the stress ratio"""
    grains = lammps_output.read_dump(os.path.join(directory, "grains.dump"))[-1]
    contacts = lammps_output.read_dump(os.path.join(directory, "contacts.dump"))[-1]
    checks = sound.static_properties(grains, contacts, width, height, pressure,
                                     depth=depth or None)
    checks["sigma_ratio"] = sigma_ratio
    return checks


def print_lines(checks, pressure):
    """LAMMPS print commands: each check beside Table I's value at the nearest
    pressure of the paper"""
    nearest, row = sound.paper_row(pressure)
    lines = [f'print "checks: the packing beside paper 003 Table I at p = {nearest:g} '
             f'(Table II for sigma1/sigma2; paper: mean +- s.d.)"']
    for key in sound.CHECKS:
        if key not in checks:
            continue
        mean, spread = row[key]
        paper = f"{mean:g}" + (f" +- {spread:g}" if spread is not None else "")
        lines.append(f'print "checks: {key:18s} {checks[key]:10.4f}   paper {paper}"')
    return lines


def json_object(checks):
    """The checks as the text of one JSON object, each value to 10 digits
    (a non-finite value as LAMMPS prints one: nan, inf; study.read_result
    reads them)"""
    return "{" + ", ".join(f"{json.dumps(key)}: {value:.10g}" for key, value in checks.items()) + "}"


def variable_line(checks):
    """The LAMMPS command that defines the string variable checks"""
    return f"variable checks string '{json_object(checks)}'"


def main(argv):
    if len(argv) != 7:
        sys.exit(__doc__)
    directory = argv[1]
    pressure, width, height, depth, sigma_ratio = (float(a) for a in argv[2:])
    checks = packing_checks(directory, pressure, width, height, depth, sigma_ratio)
    with open(os.path.join(directory, "checks.lmp"), "w") as out:
        out.write("\n".join(print_lines(checks, pressure) + [variable_line(checks)]) + "\n")


if __name__ == "__main__":
    main(sys.argv)
