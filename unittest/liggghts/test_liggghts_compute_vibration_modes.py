"""LIGGGHTS front end: compute vibration/modes (liggghts/src/compute_vibration_modes.*).

1. One packing, two engines: the frozen packing of the fix's two-engine test
   (test_liggghts_fix_acoustic_mindlin.py: 64 grains on a perturbed cubic
   lattice, Hertz contacts, E, nu, the bottom layer clamped as the fixed
   group) read by LAMMPS (pair_style granular hertz/material, its compute
   vibration/modes) and by LIGGGHTS (pair_style gran model hertz, this
   compute) with the same keywords: every mode's frequency and participation
   ratio (the local rows), the count of zero modes (the scalar), the
   histogram and the shape of a selected mode (per-atom array, relative to
   its largest component) agree to 1e-10, for model full and model normal,
   methods dense and lanczos, and with a floor plane (fix wall/gran zplane
   in both engines) as the clamped base instead of a fixed group.  Measured: every number the same bits (the two
   walkers build the same network to the last bit, and the facade makes the
   LAMMPS compute's calls).  The tolerance is not loose for every mode: the
   softest modes of model full (2.86 Hz against 10.1 kHz at the top) amplify
   a last-bit difference of the contact normals by (f_max / f)^2, to 3e-9
   relative when the LIGGGHTS walker multiplied by 1/r instead of dividing by
   r; model normal, with 24 zero modes and floppy modes near them, is
   compared on f_max.
2. 1 and 2 MPI ranks give the same frequencies and shape, bit for bit.
3. Bad inputs stop LIGGGHTS with an ERROR line naming the problem.
4. Method kpm (64 moments, 4 vectors, seed 11): the histogram the same in
   both engines; a group whose free DOFs changed after the compute was
   defined (LIGGGHTS's global vectors have a fixed length) is an ERROR.

Needs ACOUSTIC_LIGGGHTS and ACOUSTIC_LMP (see the fix's test)."""
import os

import pytest

import test_liggghts_fix_acoustic_mindlin as base
from test_liggghts_fix_acoustic_mindlin import E, NU, MU, NSOURCE, relative, run

NGRAINS = 64

LIGGGHTS_COMPUTE = """\
compute m all vibration/modes stiffness hertz {E} {NU} fixed src {extra}
thermo_style custom step atoms c_m c_m[1] {array}
thermo_modify format float %.17g
dump l all local 1 modes.local c_m[1] c_m[2] c_m[3]
dump_modify l format "%.17g %.17g %.17g"
{peratom}
"""
LIGGGHTS_PERATOM = """\
dump s all custom 1 shape.dump id c_m[1] c_m[2] c_m[3]
dump_modify s sort id format "%d %.17g %.17g %.17g"
"""

LAMMPS_DECK = """\
atom_style sphere
atom_modify map array
boundary f f f
newton off
comm_modify vel yes
units si
read_data packing.data
neighbor 2e-4 bin
neigh_modify delay 0
pair_style granular
pair_coeff * * hertz/material {E} 0.5 {NU} tangential linear_history/acoustic 1.0 0.0 {MU}
timestep 1e-6
group src id <> 1 {NSOURCE}
compute m all vibration/modes stiffness hertz {E} {NU} fixed src {extra}
thermo_style custom step atoms c_m c_m[1] {array}
thermo_modify format float %.17g
dump l all local 1 modes.local c_m[1] c_m[2] c_m[3]
dump_modify l format float %.17g
{peratom}
run 0
"""
LAMMPS_PERATOM = """\
dump s all custom 1 shape.dump id c_m[1] c_m[2] c_m[3]
dump_modify s sort id format float %.17g
"""

CASES = [
    ("model full", "model full", True),
    ("model full mode 3", "model full mode 3", True),
    ("model normal", "model normal", False),
    ("lanczos", "model full method lanczos nmodes 12 mode 2", True),
    ("histogram", "model full bins 20 0 20000", True),
    # no fixed group: the packing stands on a floor plane, a clamped wall of the
    # network (one zero mode: a rigid motion the floor's springs do not hold)
    ("on a clamped floor", "model full", False),
]

# the floor of the pulse test (fix wall/gran zplane in both engines)
Z = 0.012 * base.D
LIGGGHTS_FLOOR = ("fix floor all wall/gran model hertz tangential history primitive type 1 "
                  "zplane %.17g\n" % Z)
LAMMPS_FLOOR = ("fix floor all wall/gran granular hertz/material {E} 0.5 {NU} tangential "
                "linear_history/acoustic 1.0 0.0 {MU} zplane %.17g NULL\n" % Z)


def liggghts_deck(extra, nbins=0, peratom=False, tangential="history", floor=False):
    compute = LIGGGHTS_COMPUTE.format(E=E, NU=NU, extra=extra,
                                      array="c_m[1][2]" if nbins else "",
                                      peratom=LIGGGHTS_PERATOM if peratom else "")
    if floor:
        compute = LIGGGHTS_FLOOR + compute.replace(" fixed src", "")
    return base.LIGGGHTS_DECK.format(E=E, NU=NU, MU=MU, NSOURCE=NSOURCE, normal="hertz",
                                     tangential=tangential, fix=compute, outputs="",
                                     run="run 0")


def lammps_deck(extra, nbins=0, peratom=False, floor=False):
    deck = LAMMPS_DECK.format(E=E, NU=NU, MU=MU, NSOURCE=NSOURCE, extra=extra,
                              array="c_m[1][2]" if nbins else "",
                              peratom=LAMMPS_PERATOM if peratom else "")
    if floor:
        deck = deck.replace("compute m all vibration/modes",
                            LAMMPS_FLOOR.format(E=E, NU=NU, MU=MU) +
                            "compute m all vibration/modes").replace(" fixed src", "")
    return deck


def mode_rows(directory):
    """the local rows of the last snapshot: [(index, f, PR)]"""
    with open(os.path.join(directory, "modes.local")) as f:
        body = f.read().split("ITEM: ENTRIES")[-1].split("\n")[1:]
    rows = [[float(t) for t in line.split()] for line in body if line.strip()]
    assert all(len(r) == 3 for r in rows)
    return rows


def shape(directory):
    with open(os.path.join(directory, "shape.dump")) as f:
        body = f.read().split("ITEM: ATOMS")[-1].split("\n")[1:]
    return {int(line.split()[0]): [float(t) for t in line.split()[1:]]
            for line in body if line.strip()}


def thermo_line(directory):
    """the values of the thermo line of step 0"""
    with open(os.path.join(directory, "log.txt")) as f:
        lines = f.read().splitlines()
    for k, line in enumerate(lines):
        if line.split()[:2] == ["Step", "Atoms"]:
            return [float(t) for t in lines[k + 1].split()]
    raise AssertionError("no thermo output in %s" % directory)


@pytest.fixture(scope="module")
def exes():
    return (base.executable("ACOUSTIC_LIGGGHTS", "the LIGGGHTS executable lmp_acoustic"),
            base.executable("ACOUSTIC_LMP", "the LAMMPS executable with the ACOUSTIC package"))


# --------------------------------------------------------------------------
# 1. one packing, two engines

@pytest.mark.parametrize("name,extra,stable", CASES, ids=[c[0] for c in CASES])
def test_same_modes_as_lammps(tmp_path, exes, name, extra, stable):
    lig, lmp = exes
    nbins = 20 if "bins" in extra else 0
    peratom = "mode" in extra.replace("model", "")
    floor = "floor" in name
    run(lig, str(tmp_path / "liggghts"), liggghts_deck(extra, nbins, peratom, floor=floor))
    run(lmp, str(tmp_path / "lammps"), lammps_deck(extra, nbins, peratom, floor=floor))
    a, b = mode_rows(str(tmp_path / "liggghts")), mode_rows(str(tmp_path / "lammps"))
    ndof = 6 if "full" in extra else 3
    nmodes = 12 if "lanczos" in extra else ndof * (NGRAINS - (0 if floor else NSOURCE))
    assert len(a) == len(b) == nmodes
    assert [r[0] for r in a] == list(range(1, nmodes + 1))
    fmax = max(r[1] for r in b)
    if stable:
        # a network with no mechanism: every frequency well above 0
        worst_f = max(relative(x[1], y[1]) for x, y in zip(a, b))
    else:
        # model normal on a nearly cubic lattice: floppy modes near 0, compared on fmax
        worst_f = max(abs(x[1] - y[1]) / fmax for x, y in zip(a, b))
    worst_pr = max(relative(x[2], y[2]) for x, y in zip(a, b)) if stable else 0.0
    ta, tb = thermo_line(str(tmp_path / "liggghts")), thermo_line(str(tmp_path / "lammps"))
    print("%s: %d modes, f %.4g ... %.4g; largest relative difference LIGGGHTS - LAMMPS: f %.3g,"
          " PR %.3g; zero modes %g and %g" % (name, nmodes, b[0][1], fmax, worst_f, worst_pr,
                                             ta[2], tb[2]))
    assert worst_f <= 1e-10
    assert worst_pr <= 1e-10
    assert ta[2] == tb[2]                          # zero modes
    assert relative(ta[3], tb[3]) <= 1e-10         # c_m[1]: the lowest frequency
    if stable:
        assert ta[2] == 0 and b[0][1] > 0.0
    if nbins:
        assert ta[4] == tb[4]                      # density of bin 1 (exact counts)
    if peratom:
        sa, sb = shape(str(tmp_path / "liggghts")), shape(str(tmp_path / "lammps"))
        assert sorted(sa) == sorted(sb) == list(range(1, NGRAINS + 1))
        largest = max(abs(v) for row in sb.values() for v in row)
        worst = max(abs(x - y) for k in sa for x, y in zip(sa[k], sb[k])) / largest
        print("  mode shape: largest difference %.3g of its largest component" % worst)
        assert worst <= 1e-10
        assert all(sa[k] == [0.0, 0.0, 0.0] for k in range(1, NSOURCE + 1))


# --------------------------------------------------------------------------
# 2. 1 and 2 ranks

def test_one_and_two_ranks(tmp_path, exes):
    lig, _ = exes
    deck = liggghts_deck("model full mode 2", peratom=True)
    run(lig, str(tmp_path / "np1"), deck)
    run(lig, str(tmp_path / "np2"), deck, nranks=2)
    a, b = mode_rows(str(tmp_path / "np1")), mode_rows(str(tmp_path / "np2"))
    assert a == b
    assert shape(str(tmp_path / "np1")) == shape(str(tmp_path / "np2"))
    assert thermo_line(str(tmp_path / "np1")) == thermo_line(str(tmp_path / "np2"))


# --------------------------------------------------------------------------
# 3. bad inputs

BAD = [
    ("no stiffness", "compute m all vibration/modes model full", "stiffness hertz E nu is required"),
    ("stiffness pair", "compute m all vibration/modes stiffness pair", "only 'hertz E nu'"),
    ("unknown keyword", "compute m all vibration/modes stiffness hertz 1e7 0.3 colour red",
     "unknown keyword 'colour'"),
    ("method", "compute m all vibration/modes stiffness hertz 1e7 0.3 method arnoldi",
     "method must be dense, lanczos or kpm"),
    ("kpm without bins", "compute m all vibration/modes stiffness hertz 1e7 0.3 method kpm",
     "give its range with bins"),
    ("nmodes with dense", "compute m all vibration/modes stiffness hertz 1e7 0.3 nmodes 4",
     "nmodes applies to method lanczos"),
    ("damping", "compute m all vibration/modes stiffness hertz 1e7 0.3 damping 0.1",
     "keyword damping does not apply"),
    ("no fixed group", "compute m all vibration/modes stiffness hertz 1e7 0.3 fixed nowhere",
     "no group 'nowhere'"),
    ("bad nu", "compute m all vibration/modes stiffness hertz 1e7 0.7", "-1 < nu < 0.5"),
    ("not a number", "compute m all vibration/modes stiffness hertz 1e7x 0.3", "not a finite number"),
    ("mode out of range",
     "compute m all vibration/modes stiffness hertz 1e7 0.3 fixed src mode 500\n"
     "thermo_style custom step c_m", "mode 500 is out of range"),
    ("everything fixed",
     "compute m src vibration/modes stiffness hertz 1e7 0.3 fixed src\nthermo_style custom step c_m",
     "no degree of freedom is left"),
    ("fixed outside the group",
     "compute m free vibration/modes stiffness hertz 1e7 0.3 fixed src\nthermo_style custom step c_m",
     "fixed group src has no atom in the compute group"),
]


@pytest.mark.parametrize("name,command,message", BAD, ids=[b[0] for b in BAD])
def test_bad_input(tmp_path, exes, name, command, message):
    lig, _ = exes
    deck = base.LIGGGHTS_DECK.format(E=E, NU=NU, MU=MU, NSOURCE=NSOURCE, normal="hertz",
                                     tangential="history", fix=command, outputs="", run="run 0")
    proc = run(lig, str(tmp_path), deck, expect_error=True)
    errors = [line for line in proc.stdout.splitlines() if line.startswith("ERROR")]
    assert errors, proc.stdout[-2000:]
    print(errors[0])
    assert message in errors[0], errors[0]


# --------------------------------------------------------------------------
# 4. method kpm (no vector, no local rows: the histogram through thermo), and
#    a group whose free DOFs change after the compute is defined

def kpm_deck(deck):
    lines = [line for line in deck.splitlines() if not line.startswith(("dump l", "dump_modify l"))]
    deck = "\n".join(lines) + "\n"
    return deck.replace("c_m c_m[1] ", "c_m ")


def test_kpm_same_as_lammps(tmp_path, exes):
    lig, lmp = exes
    extra = "model full method kpm bins 20 0 20000 moments 64 vectors 4 seed 11"
    array = "c_m[1][2]"
    ldeck = kpm_deck(liggghts_deck(extra, nbins=20)).replace(array, "c_m[3][2] c_m[7][2] c_m[7][3]")
    mdeck = kpm_deck(lammps_deck(extra, nbins=20)).replace(array, "c_m[3][2] c_m[7][2] c_m[7][3]")
    run(lig, str(tmp_path / "liggghts"), ldeck)
    run(lmp, str(tmp_path / "lammps"), mdeck)
    ta, tb = thermo_line(str(tmp_path / "liggghts")), thermo_line(str(tmp_path / "lammps"))
    print("kpm: LIGGGHTS %s, LAMMPS %s" % (ta, tb))
    assert ta[4] > 0.0 and ta[5] > 0.0
    assert max(relative(x, y) for x, y in zip(ta[2:], tb[2:])) <= 1e-10


def test_group_changed_since_defined(tmp_path, exes):
    lig, _ = exes
    command = ("compute m all vibration/modes stiffness hertz 1e7 0.3 fixed src\n"
               "thermo_style custom step c_m[1]\nrun 0\ndelete_atoms group top")
    deck = base.LIGGGHTS_DECK.format(E=E, NU=NU, MU=MU, NSOURCE=NSOURCE, normal="hertz",
                                     tangential="history",
                                     fix="group top id <> 49 64\n" + command, outputs="",
                                     run="run 0")
    proc = run(lig, str(tmp_path), deck, expect_error=True)
    errors = [line for line in proc.stdout.splitlines() if line.startswith("ERROR")]
    assert errors, proc.stdout[-2000:]
    print(errors[0])
    assert "free DOFs now, 144 when the compute was defined" in errors[0], errors[0]
