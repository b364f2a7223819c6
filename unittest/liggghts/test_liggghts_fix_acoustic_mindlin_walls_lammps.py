"""LIGGGHTS front end: fix acoustic/mindlin with a vibrating floor, against
LAMMPS.

The frozen 64-grain packing of test_liggghts_fix_acoustic_mindlin.py stands
on a floor plane at z = 0.012 d that overlaps every grain of its bottom layer
(0.3-2 % of d), the floor the source: LAMMPS with fix wall/gran granular
hertz/material ... tangential linear_history/acoustic ... zplane and
source wall floor, LIGGGHTS with fix wall/gran model hertz tangential
history/acoustic primitive type 1 zplane and source wall floor (its default
direction, the plane's normal, and an oblique one).  After run 0 every
contact, the 16 floor contacts included (atom ID 0 for the wall in both
engines' rows), has the same F_n, k_n, U_t and s in both to 1e-10
relative; LIGGGHTS's pair and wall contact histories hold 1 - s bit for
bit.  The same on 2 ranks of LIGGGHTS (to 1e-12 of 1 rank).

Needs ACOUSTIC_LIGGGHTS and ACOUSTIC_LMP."""
import os

import pytest

import test_liggghts_fix_acoustic_mindlin as base

D = base.D
Z = 0.012 * D
NCONTACTS = base.NCONTACTS + base.NSOURCE

LIGGGHTS_WALL = ("fix floor all wall/gran model hertz tangential history/acoustic "
                 "primitive type 1 zplane %.17g\n"
                 "dump w all custom 1 wall.history id f_history_floor[1] f_history_floor[2] "
                 "f_history_floor[3] f_history_floor[4]\n"
                 "dump_modify w sort id format \"%%d %%.17g %%.17g %%.17g %%.17g\"\n" % Z)
LIGGGHTS_FIX = ("fix us all acoustic/mindlin 1 frequency {f} amplitude {U0} source wall floor "
                "stiffness hertz {E} {NU} model full {extra}")

LAMMPS_WALL = ("fix floor all wall/gran granular hertz/material {E} 0.5 {NU} tangential "
               "linear_history/acoustic 1.0 0.0 {MU} zplane %.17g NULL\n" % Z)


def lammps_deck(f, U0, extra):
    deck = base.LAMMPS_DECK.format(E=base.E, NU=base.NU, MU=base.MU, NSOURCE=base.NSOURCE, f=f,
                                   U0=U0, extra=extra)
    deck = deck.replace("source src", "source wall floor")
    wall = LAMMPS_WALL.format(E=base.E, NU=base.NU, MU=base.MU)
    return deck.replace("fix us all", wall + "fix us all")


def liggghts_deck(f, U0, extra):
    fix = LIGGGHTS_WALL + LIGGGHTS_FIX.format(f=f, U0=U0, E=base.E, NU=base.NU, extra=extra)
    return base.liggghts_deck(f, U0, fix=fix)


def wall_history(path):
    with open(path) as f:
        body = f.read().split("ITEM: ATOMS")[-1].split("\n")[1:]
    return {int(l.split()[0]): [float(t) for t in l.split()[1:]] for l in body if l.strip()}


@pytest.fixture(scope="module")
def exes():
    return (base.executable("ACOUSTIC_LIGGGHTS", "the LIGGGHTS executable lmp_acoustic"),
            base.executable("ACOUSTIC_LMP", "the LAMMPS executable with the ACOUSTIC package"))


@pytest.mark.parametrize("f,U0,extra", [
    (3000.0, 1e-4, ""), (1000.0, 1e-5, ""),
    (3000.0, 1e-4, "direction 1 0 1 model normal")])
def test_floor_source_same_as_lammps(tmp_path, exes, f, U0, extra):
    lig, lmp = exes
    base.run(lig, str(tmp_path / "liggghts"), liggghts_deck(f, U0, extra))
    base.run(lmp, str(tmp_path / "lammps"), lammps_deck(f, U0, extra))
    a = base.local_rows(str(tmp_path / "liggghts" / "fix.contacts"), 6)
    b = base.local_rows(str(tmp_path / "lammps" / "fix.contacts"), 6)
    assert len(a) == NCONTACTS, len(a)
    assert sorted(a) == sorted(b)
    walls = [k for k in a if k[0] == 0]
    assert len(walls) == base.NSOURCE
    worst = {}
    for name, col in (("F_n", 2), ("k_n", 3), ("U_t", 4), ("s", 5)):
        worst[name] = max(base.relative(a[k][col], b[k][col]) for k in a)
    worst_wall = max(base.relative(a[k][c], b[k][c]) for k in walls for c in (2, 3, 4, 5))
    print("f = %g, U0 = %g %s: largest relative differences LIGGGHTS - LAMMPS %s, "
          "floor contacts %g" % (f, U0, extra, worst, worst_wall))
    for name, value in worst.items():
        assert value <= 1e-10, (name, value)
    # the floor drives: factors below 1, the floor contacts' among them
    assert min(row[5] for row in a.values()) < 0.99
    assert min(a[k][5] for k in walls) < 1.0
    hist = base.local_rows(str(tmp_path / "liggghts" / "pair.history"), 7)
    for k in hist:
        assert hist[k][6] == 1.0 - a[k][5], k
    wall = wall_history(str(tmp_path / "liggghts" / "wall.history"))
    for k in walls:
        assert wall[k[1]][3] == 1.0 - a[k][5], k


def test_floor_source_two_ranks(tmp_path, exes):
    lig = exes[0]
    rows = {}
    for nranks in (1, 2):
        d = str(tmp_path / ("np%d" % nranks))
        base.run(lig, d, liggghts_deck(3000.0, 1e-4, ""), nranks=nranks)
        rows[nranks] = base.local_rows(os.path.join(d, "fix.contacts"), 6)
    a, b = rows[1], rows[2]
    assert len(a) == NCONTACTS and sorted(a) == sorted(b)
    worst = max(base.relative(a[k][c], b[k][c]) for k in a for c in (2, 3, 4, 5))
    print("floor source: largest relative difference 1 - 2 ranks %g" % worst)
    assert worst <= 1e-12
