"""LIGGGHTS front end: compute vibration/pulse (liggghts/src/compute_vibration_pulse.*).

1. One packing, two engines: the frozen packing of the fix's two-engine test
   (64 grains, Hertz contacts; the bottom layer the source, the top layer
   the detector) read by LAMMPS (pair_style granular hertz/material, its
   compute vibration/pulse) and by LIGGGHTS (pair_style gran model hertz,
   this compute) with the same keywords: the signal F_sig(t) (the global
   array, printed with 20 digits) agrees to 1e-10 of its largest value, the
   global vector (time step, steps, free DOFs) likewise; method modes with
   initial velocity and displacement, model full and normal, an oblique
   direction, and method integrate with damping (5 100 steps); the
   snapshot (per-atom array); a floor plane (fix wall/gran zplane in both
   engines) as the source, as the detector, and clamped under a pulse
   between grain groups.  Measured: the same bits in every case.  An STL
   mesh floor as the source (source mesh ID) gives the primitive floor's
   signal in LIGGGHTS.
2. 1 and 2 MPI ranks give the same signal, bit for bit.
3. Bad inputs stop LIGGGHTS with an ERROR line naming the problem.

Needs ACOUSTIC_LIGGGHTS and ACOUSTIC_LMP (see the fix's test)."""
import os

import pytest

import test_liggghts_fix_acoustic_mindlin as base
from test_liggghts_fix_acoustic_mindlin import E, NU, MU, NSOURCE, relative, run

NGRAINS = 64
SAMPLES = 101
DURATION = 2e-3
GROUPS = "group top id <> 49 64\ngroup middle id <> 17 48\ngroup det id <> 1 4\n"
SIZES = {"src": NSOURCE, "top": 16, "middle": 32, "det": 4}

COMPUTE = """\
compute p all vibration/pulse {ends} stiffness hertz {E} {NU} duration {T} samples {n} {extra}
thermo_style custom step atoms c_p[1] c_p[2] c_p[3] c_p[1][2]
thermo_modify format float %.17g
{peratom}
run 0
variable k loop {n}
label sample
variable t equal c_p[${{k}}][1]
variable f equal c_p[${{k}}][2]
print "$(v_t) $(v_f)" append pulse.txt
next k
jump SELF sample
"""
# the snapshot in both engines' dump custom
LIGGGHTS_PERATOM = """\
dump s all custom 1 snapshot.dump id c_p[1] c_p[2] c_p[3]
dump_modify s sort id format "%d %.17g %.17g %.17g"
"""
LAMMPS_PERATOM = """\
dump s all custom 1 snapshot.dump id c_p[1] c_p[2] c_p[3]
dump_modify s sort id format float %.17g
"""

LAMMPS_HEAD = """\
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
"""

GRAINS = "source src detector top"
# a floor plane under the packing, overlapping its bottom layer (as the fix's wall test)
Z = 0.012 * base.D
LIGGGHTS_FLOOR = ("fix floor all wall/gran model hertz tangential history primitive type 1 "
                  "zplane %.17g\n" % Z)
LAMMPS_FLOOR = ("fix floor all wall/gran granular hertz/material {E} 0.5 {NU} tangential "
                "linear_history/acoustic 1.0 0.0 {MU} zplane %.17g NULL\n" % Z)

CASES = [
    ("velocity full", GRAINS, "model full"),
    ("displacement full", GRAINS, "model full initial displacement"),
    ("normal oblique", GRAINS, "model normal direction 1 0.5 2 method modes"),
    ("damped integrate", GRAINS, "model full damping 0.05 method integrate"),
    ("snapshot", GRAINS, "model full snapshot 5e-4"),
    ("floor source", "source wall floor detector top", "model full"),
    ("floor detector", "source top detector wall floor", "model full initial displacement"),
    # the pulse from the top reaches 4 grains of the bottom layer through its
    # 12 others, which stand on the clamped floor
    ("grains on a clamped floor", "source top detector det", "model full"),
]


def compute_lines(ends, extra, peratom):
    return COMPUTE.format(ends=ends, E=E, NU=NU, T=DURATION, n=SAMPLES, extra=extra,
                          peratom=peratom)


def liggghts_deck(extra="model full", peratom=False, command=None, ends=GRAINS, floor=False):
    body = GROUPS + (LIGGGHTS_FLOOR if floor else "") + (
        command if command is not None else
        compute_lines(ends, extra, LIGGGHTS_PERATOM if peratom else ""))
    # the deck runs itself (run 0 inside the compute's lines)
    return base.LIGGGHTS_DECK.format(E=E, NU=NU, MU=MU, NSOURCE=NSOURCE, normal="hertz",
                                     tangential="history", fix=body, outputs="", run="")


def lammps_deck(extra, peratom=False, ends=GRAINS, floor=False):
    return (LAMMPS_HEAD.format(E=E, NU=NU, MU=MU, NSOURCE=NSOURCE) + GROUPS +
            (LAMMPS_FLOOR.format(E=E, NU=NU, MU=MU) if floor else "") +
            compute_lines(ends, extra, LAMMPS_PERATOM if peratom else ""))


def signal(directory):
    with open(os.path.join(directory, "pulse.txt")) as f:
        rows = [[float(t) for t in line.split()] for line in f if line.strip()]
    assert len(rows) == SAMPLES
    return rows


def thermo_line(directory):
    with open(os.path.join(directory, "log.txt")) as f:
        lines = f.read().splitlines()
    for k, line in enumerate(lines):
        if line.split()[:2] == ["Step", "Atoms"]:
            return [float(t) for t in lines[k + 1].split()]
    raise AssertionError("no thermo output in %s" % directory)


def snapshot(directory):
    with open(os.path.join(directory, "snapshot.dump")) as f:
        body = f.read().split("ITEM: ATOMS")[-1].split("\n")[1:]
    return {int(line.split()[0]): [float(t) for t in line.split()[1:]]
            for line in body if line.strip()}


@pytest.fixture(scope="module")
def exes():
    return (base.executable("ACOUSTIC_LIGGGHTS", "the LIGGGHTS executable lmp_acoustic"),
            base.executable("ACOUSTIC_LMP", "the LAMMPS executable with the ACOUSTIC package"))


# --------------------------------------------------------------------------
# 1. one packing, two engines

@pytest.mark.parametrize("name,ends,extra", CASES, ids=[c[0] for c in CASES])
def test_same_signal_as_lammps(tmp_path, exes, name, ends, extra):
    lig, lmp = exes
    peratom = "snapshot" in extra
    floor = "floor" in name
    run(lig, str(tmp_path / "liggghts"), liggghts_deck(extra, peratom, ends=ends, floor=floor))
    run(lmp, str(tmp_path / "lammps"), lammps_deck(extra, peratom, ends=ends, floor=floor))
    a, b = signal(str(tmp_path / "liggghts")), signal(str(tmp_path / "lammps"))
    assert [r[0] for r in a] == [r[0] for r in b]
    assert abs(a[-1][0] - DURATION) <= 1e-15 * DURATION
    largest = max(abs(r[1]) for r in b)
    worst = max(abs(x[1] - y[1]) for x, y in zip(a, b)) / largest
    ta, tb = thermo_line(str(tmp_path / "liggghts")), thermo_line(str(tmp_path / "lammps"))
    print("%s: max |F_sig| %.4g N, largest difference LIGGGHTS - LAMMPS %.3g of it; "
          "time step %g, steps %g, free DOFs %g" % (name, largest, worst, ta[2], ta[3], ta[4]))
    assert largest > 0.0
    assert worst <= 1e-10
    ndof = 6 if "full" in extra else 3
    words = ends.split()
    groups = [words[k + 1] for k in range(len(words) - 1)
              if words[k] in ("source", "detector") and words[k + 1] != "wall"]
    prescribed = sum(SIZES[g] for g in groups)
    assert ta[4] == tb[4] == ndof * (NGRAINS - prescribed)
    assert ta[3] == tb[3]                          # steps (integrate), 0 (modes)
    assert relative(ta[2], tb[2]) <= 1e-10         # the time step of integrate
    if peratom:
        sa, sb = snapshot(str(tmp_path / "liggghts")), snapshot(str(tmp_path / "lammps"))
        assert sorted(sa) == sorted(sb) == list(range(1, NGRAINS + 1))
        scale = max(abs(v) for row in sb.values() for v in row)
        diff = max(abs(x - y) for k in sa for x, y in zip(sa[k], sb[k])) / scale
        print("  snapshot: largest difference %.3g of its largest component" % diff)
        assert scale > 0.0 and diff <= 1e-10


# --------------------------------------------------------------------------
# 1b. a mesh floor (an STL square of two triangles in the floor's plane) as
#     the source gives the primitive floor's signal (LAMMPS has no mesh)

MESH_FLOOR = ("fix stl all mesh/surface file floor.stl type 1\n"
              "fix floor all wall/gran model hertz tangential history mesh n_meshes 1 "
              "meshes stl\n")


def write_floor_stl(directory):
    os.makedirs(directory, exist_ok=True)
    lo, hi = -base.D, (base.NSIDE + 1) * base.D
    with open(os.path.join(directory, "floor.stl"), "w") as f:
        f.write("solid floor\n")
        for tri in (((lo, lo), (hi, lo), (hi, hi)), ((lo, lo), (hi, hi), (lo, hi))):
            f.write(" facet normal 0 0 1\n  outer loop\n")
            for x, y in tri:
                f.write("   vertex %.17g %.17g %.17g\n" % (x, y, Z))
            f.write("  endloop\n endfacet\n")
        f.write("endsolid floor\n")


def test_mesh_floor_source(tmp_path, exes):
    lig, _ = exes
    extra = "model full direction 0 0 1"
    run(lig, str(tmp_path / "primitive"),
        liggghts_deck(extra, ends="source wall floor detector top", floor=True))
    write_floor_stl(str(tmp_path / "mesh"))
    deck = liggghts_deck(extra, ends="source mesh stl detector top").replace(
        "compute p all", MESH_FLOOR + "compute p all")
    run(lig, str(tmp_path / "mesh"), deck)
    a, b = signal(str(tmp_path / "mesh")), signal(str(tmp_path / "primitive"))
    largest = max(abs(r[1]) for r in b)
    worst = max(abs(x[1] - y[1]) for x, y in zip(a, b)) / largest
    print("mesh floor against primitive floor: largest difference %.3g of max |F_sig| %.4g"
          % (worst, largest))
    assert largest > 0.0 and worst <= 1e-10
    assert thermo_line(str(tmp_path / "mesh"))[4] == 6 * (NGRAINS - NSOURCE)


# --------------------------------------------------------------------------
# 2. 1 and 2 ranks

@pytest.mark.parametrize("ends,extra,floor", [
    (GRAINS, "model full", False), (GRAINS, "model full damping 0.05", False),
    ("source wall floor detector top", "model full", True)])
def test_one_and_two_ranks(tmp_path, exes, ends, extra, floor):
    lig, _ = exes
    deck = liggghts_deck(extra, ends=ends, floor=floor)
    run(lig, str(tmp_path / "np1"), deck)
    run(lig, str(tmp_path / "np2"), deck, nranks=2)
    assert signal(str(tmp_path / "np1")) == signal(str(tmp_path / "np2"))
    assert thermo_line(str(tmp_path / "np1")) == thermo_line(str(tmp_path / "np2"))


# --------------------------------------------------------------------------
# 3. bad inputs

HEAD = "compute p all vibration/pulse "
STIFF = " stiffness hertz 1e7 0.3 "
BAD = [
    ("source wall", HEAD + "source wall w detector top" + STIFF + "duration 1\nrun 0",
     "source wall w is not a wall of the vibration network"),
    ("mesh as wall", MESH_FLOOR + HEAD + "source wall stl detector top" + STIFF +
     "duration 1\nrun 0", "source wall stl is a mesh (fix mesh/surface): write 'source mesh stl'"),
    ("wall as mesh", LIGGGHTS_FLOOR + HEAD + "source mesh floor detector top" + STIFF +
     "duration 1\nrun 0", "write 'source wall floor'"),
    ("mesh without direction", MESH_FLOOR + HEAD + "source mesh stl detector top" + STIFF +
     "duration 1\nrun 0", "give the direction of the pulse"),
    ("same wall", LIGGGHTS_FLOOR + HEAD + "source wall floor detector wall floor" + STIFF +
     "duration 1\nrun 0", "the source and the detector are the same wall floor"),
    ("no source", HEAD + "detector top" + STIFF + "duration 1", "'source' belongs"),
    ("no group", HEAD + "source nowhere detector top" + STIFF + "duration 1", "no group 'nowhere'"),
    ("no duration", HEAD + "source src detector top" + STIFF, "duration T"),
    ("no stiffness", HEAD + "source src detector top duration 1", "stiffness hertz E nu is required"),
    ("unknown keyword", HEAD + "source src detector top" + STIFF + "duration 1 colour red",
     "unknown keyword 'colour'"),
    ("modes with damping", HEAD + "source src detector top" + STIFF + "duration 1 damping 0.1 "
     "method modes", "method modes needs an undamped network"),
    ("zero direction", HEAD + "source src detector top" + STIFF + "duration 1 direction 0 0 0",
     "zero vector"),
    ("samples", HEAD + "source src detector top" + STIFF + "duration 1 samples 1", "samples must be"),
    ("snapshot after the end", HEAD + "source src detector top" + STIFF + "duration 1 snapshot 2",
     "after the duration"),
    ("source is detector", HEAD + "source src detector src" + STIFF + "duration 1\nrun 0",
     "in both the source group src and the detector group src"),
    ("detector outside", "compute p free vibration/pulse source middle detector src" + STIFF +
     "duration 1\nrun 0", "detector group src has no atom in the compute group free"),
    ("too many steps", HEAD + "source src detector top" + STIFF + "duration 1 method integrate "
     "max_steps 10\nthermo_style custom step c_p[1]\nrun 0", "max_steps"),
]


@pytest.mark.parametrize("name,command,message", BAD, ids=[b[0] for b in BAD])
def test_bad_input(tmp_path, exes, name, command, message):
    lig, _ = exes
    write_floor_stl(str(tmp_path))
    proc = run(lig, str(tmp_path), liggghts_deck(command=command), expect_error=True)
    errors = [line for line in proc.stdout.splitlines() if line.startswith("ERROR")]
    assert errors, proc.stdout[-2000:]
    print(errors[0])
    assert message in errors[0], errors[0]
