"""LIGGGHTS front end: fix acoustic/mindlin with walls (primitive walls and
STL meshes of fix wall/gran as network nodes of infinite mass).

1. The column: 5 grains stacked in a zig-zag (contact normals tilted by
   +-0.2 rad) on a floor, no gravity, frozen (run 0), model normal; the floor
   is a primitive zplane (source wall) or an STL mesh plane of two triangles
   (source mesh, direction given).  The network's steady response is solved
   independently here (numpy: the 15 x 15 system (K - w^2 M) u = b of the
   normal springs, F_n and k_n from the Hertz formulas and the geometry), and
   every contact's F_n, k_n, U_t and s (the wall contact included) agree with
   the fix's local rows to 1e-8 relative; the wall's history holds 1 - s
   (the mesh's: one contact, through compute wall/gran/local).
2. Restart: write_restart after a run of 20 steps with the fix (primitive
   floor, and mesh floor), a new run without the fix reads it; the pair and
   the wall contact histories (the primitive wall's per-atom history, the
   mesh's contact tracker through compute wall/gran/local) hold the factors
   of the first run, bit for bit.
3. Bad inputs (unknown wall or mesh ID, a mesh source without direction, a
   wall given as mesh, ...) stop LIGGGHTS with an ERROR line naming the
   problem, on 1 and 2 ranks.

Needs ACOUSTIC_LIGGGHTS (lmp_acoustic) and mpirun for the 2-rank runs."""
import math
import os
import shutil
import subprocess

import numpy as np
import pytest

E, NU, MU, RHO = 1e7, 0.3, 0.5, 2500.0
R = 5e-4
N = 5
F, U0 = 3000.0, 2e-5
RATIO = 2.0 / 7.0
XC, YC = 0.3e-3, -0.2e-3       # off the mesh's diagonal edge
L = 4e-3                       # half side of the mesh square


def column():
    """positions of the column, the wall overlap and the pair overlaps"""
    wall_overlap = 1.2e-5
    pos = [np.array([XC, YC, R - wall_overlap])]
    overlaps = []
    for k in range(N - 1):
        theta = 0.2 if k % 2 == 0 else -0.2
        delta = 1e-5 * (1 + 0.3 * k)
        overlaps.append(delta)
        e = np.array([math.sin(theta), 0.0, math.cos(theta)])
        pos.append(pos[-1] + (2 * R - delta) * e)
    return pos, wall_overlap


def write_data(directory):
    pos, _ = column()
    with open(os.path.join(directory, "column.data"), "w") as f:
        f.write("column\n\n%d atoms\n1 atom types\n\n" % N)
        f.write("%.17g %.17g xlo xhi\n%.17g %.17g ylo yhi\n%.17g %.17g zlo zhi\n\n"
                % (-L, L, -L, L, -2e-3, 8e-3))
        f.write("Atoms\n\n")
        for k, p in enumerate(pos):
            f.write("%d 1 %.17g %.17g %.17g %.17g %.17g\n" % (k + 1, 2 * R, RHO, p[0], p[1], p[2]))
    # an STL floor at z = 0: a square of two triangles, normal +z
    with open(os.path.join(directory, "floor.stl"), "w") as f:
        f.write("solid floor\n")
        for tri in (((-L, -L), (L, -L), (L, L)), ((-L, -L), (L, L), (-L, L))):
            f.write(" facet normal 0 0 1\n  outer loop\n")
            for x, y in tri:
                f.write("   vertex %.17g %.17g 0\n" % (x, y))
            f.write("  endloop\n endfacet\n")
        f.write("endsolid floor\n")


DECK = """\
atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
processors * 1 1
units si
{read}
neighbor 2e-4 bin
neigh_modify delay 0
fix m1 all property/global youngsModulus peratomtype {E}
fix m2 all property/global poissonsRatio peratomtype {NU}
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.5
fix m4 all property/global coefficientFriction peratomtypepair 1 {MU}
fix m5 all property/global characteristicVelocity scalar 1.0
pair_style gran model hertz tangential history/acoustic
pair_coeff * *
timestep 1e-7
{walls}
{fix}
compute pgl all pair/gran/local id history
thermo_style custom step atoms f_us[1] f_us[2] f_us[3]
thermo_modify format float %.17g
dump c all local 1 fix.contacts f_us[1] f_us[2] f_us[3] f_us[4] f_us[5] f_us[6]
dump_modify c format "%.17g %.17g %.17g %.17g %.17g %.17g"
dump h all local 1 pair.history c_pgl[1] c_pgl[2] c_pgl[3] c_pgl[4] c_pgl[5] c_pgl[6] c_pgl[7]
dump_modify h format "%.17g %.17g %.17g %.17g %.17g %.17g %.17g"
{after}
"""

PRIMITIVE = ("fix floor all wall/gran model hertz tangential history/acoustic "
             "primitive type 1 zplane 0.0")
MESH = ("fix stl all mesh/surface file floor.stl type 1\n"
        "fix floor all wall/gran model hertz tangential history/acoustic mesh n_meshes 1 "
        "meshes stl")
FIX = ("fix us all acoustic/mindlin 1 frequency {f} amplitude {U0} source {source} "
       "stiffness hertz {E} {NU} model normal {extra}")
# the mesh's contact histories: compute wall/gran/local (last column 1 - s);
# with the fix on the first run it also checks that the mesh's contact
# tracker stays consistent (it crashed when its partner counts were reset
# under the partners the fix had registered)
MESH_HISTORY = ("compute wgl all wall/gran/local id history\n"
                "dump m all local 1 mesh.history c_wgl[1] c_wgl[2] c_wgl[3] c_wgl[4] c_wgl[5] "
                "c_wgl[6] c_wgl[7]\n"
                "dump_modify m format \"%.17g %.17g %.17g %.17g %.17g %.17g %.17g\"")
# the primitive wall's history: a per-atom fix property/atom (last value 1 - s)
WALL_HISTORY = ("dump w all custom 1 wall.history id f_history_floor[1] f_history_floor[2] "
                "f_history_floor[3] f_history_floor[4]\n"
                "dump_modify w sort id format \"%d %.17g %.17g %.17g %.17g\"")


def executable(name, what):
    exe = os.environ.get(name)
    if not exe:
        pytest.fail("%s is not set: set it to %s" % (name, what))
    return os.path.abspath(exe)


def run_env():
    env = dict(os.environ)
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    env.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")
    env.setdefault("OMPI_MCA_mpi_yield_when_idle", "1")
    return env


def run(exe, directory, deck, nranks=1, expect_error=False, deckname="in.deck"):
    os.makedirs(directory, exist_ok=True)
    write_data(directory)
    with open(os.path.join(directory, deckname), "w") as f:
        f.write(deck)
    cmd = [exe, "-in", deckname, "-log", "log.txt", "-echo", "log"]
    if nranks > 1:
        mpirun = shutil.which("mpirun")
        if mpirun is None:
            pytest.fail("mpirun is not on PATH (needed for the %d-rank runs)" % nranks)
        cmd = [mpirun, "-np", str(nranks)] + cmd
    proc = subprocess.run(cmd, cwd=directory, env=run_env(), stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, universal_newlines=True, errors="replace",
                          timeout=300)
    if expect_error:
        return proc
    if proc.returncode != 0 or "ERROR" in proc.stdout:
        pytest.fail("run failed (%s) in %s:\n%s" % (proc.returncode, directory, proc.stdout[-3000:]))
    return proc


def deck(walls, source, extra="", fix=None, read="read_data column.data", after="run 0"):
    if fix is None:
        fix = FIX.format(f=F, U0=U0, source=source, E=E, NU=NU, extra=extra)
    return DECK.format(E=E, NU=NU, MU=MU, walls=walls, fix=fix, read=read, after=after)


def local_rows(path, ncols):
    """the last snapshot of a dump local: {(lower ID, higher ID): row}, a wall's ID 0"""
    with open(path) as f:
        text = f.read()
    body = text.split("ITEM: ENTRIES")[-1].split("\n")[1:]
    rows = {}
    for line in body:
        if not line.strip():
            continue
        values = [float(t) for t in line.split()]
        assert len(values) == ncols, line
        a, b = int(values[0]), int(values[1])
        key = (min(a, b), max(a, b))
        assert key not in rows, "contact %s twice" % (key,)
        rows[key] = values
    return rows


def atom_rows(path):
    with open(path) as f:
        body = f.read().split("ITEM: ATOMS")[-1].split("\n")[1:]
    return {int(l.split()[0]): [float(t) for t in l.split()[1:]] for l in body if l.strip()}


def mesh_rows(path):
    """the last snapshot of the mesh's dump local, a list of rows"""
    with open(path) as f:
        body = f.read().split("ITEM: ENTRIES")[-1].split("\n")[1:]
    return [[float(t) for t in l.split()] for l in body if l.strip()]


def relative(x, y):
    if x == y:
        return 0.0
    return abs(x - y) / max(abs(x), abs(y))


@pytest.fixture(scope="module")
def lig():
    return executable("ACOUSTIC_LIGGGHTS", "the LIGGGHTS executable lmp_acoustic")


# --------------------------------------------------------------------------
# 1. the column against its exact solution

def reference(direction):
    """F_n, k_n, U_t, s of every contact, keyed as the dump: (0, 1) the wall"""
    pos, wall_overlap = column()
    estar = E / (2 * (1 - NU * NU))          # LIGGGHTS's Yeff of one material
    mass = RHO * 4.0 / 3.0 * math.pi * R ** 3
    omega = 2 * math.pi * F
    d = np.array(direction, dtype=float)
    d /= np.linalg.norm(d)

    def hertz(rstar, delta):
        fn = 4.0 / 3.0 * estar * math.sqrt(rstar * delta) * delta
        kappa = 4.0 / 3.0 * estar * math.sqrt(rstar)
        return fn, 1.5 * kappa ** (2.0 / 3.0) * fn ** (1.0 / 3.0)

    contacts = []    # (i, j or None, n from j to i, F_n, k_n)
    fn, kn = hertz(R, wall_overlap)
    contacts.append((0, None, np.array([0.0, 0.0, 1.0]), fn, kn))
    for k in range(N - 1):
        dx = pos[k + 1] - pos[k]
        dist = np.linalg.norm(dx)
        fn, kn = hertz(R / 2, 2 * R - dist)
        contacts.append((k + 1, k, dx / dist, fn, kn))
    A = -omega ** 2 * mass * np.eye(3 * N)
    b = np.zeros(3 * N)
    for i, j, n, fn, kn in contacts:
        block = kn * np.outer(n, n)
        A[3 * i:3 * i + 3, 3 * i:3 * i + 3] += block
        if j is None:
            b[3 * i:3 * i + 3] += block @ d
        else:
            A[3 * j:3 * j + 3, 3 * j:3 * j + 3] += block
            A[3 * i:3 * i + 3, 3 * j:3 * j + 3] -= block
            A[3 * j:3 * j + 3, 3 * i:3 * i + 3] -= block
    u = np.linalg.solve(A, b)
    rows = {}
    for i, j, n, fn, kn in contacts:
        uj = d if j is None else u[3 * j:3 * j + 3]
        delta = u[3 * i:3 * i + 3] - uj
        ut = U0 * np.linalg.norm(delta - np.dot(delta, n) * n)
        s = min(max(1.0 - RATIO * kn * ut / (MU * fn), 0.0), 1.0)
        key = (0, i + 1) if j is None else (j + 1, i + 1)
        rows[key] = (fn, kn, ut, s)
    return rows


@pytest.mark.parametrize("floor", ["primitive", "mesh"])
def test_column_exact(tmp_path, lig, floor):
    direction = (0.3, 0.0, 1.0)
    if floor == "primitive":
        walls, source = PRIMITIVE + "\n" + WALL_HISTORY, "wall floor"
    else:
        walls, source = MESH + "\n" + MESH_HISTORY, "mesh stl"
    extra = "direction %g %g %g" % direction
    run(lig, str(tmp_path), deck(walls, source, extra))
    got = local_rows(str(tmp_path / "fix.contacts"), 6)
    ref = reference(direction)
    assert sorted(got) == sorted(ref)
    utmax = max(r[2] for r in ref.values())
    worst = {}
    for name, col in (("F_n", 2), ("k_n", 3), ("s", 5)):
        worst[name] = max(relative(got[k][col], ref[k][col - 2]) for k in ref)
    worst["U_t"] = max(abs(got[k][4] - ref[k][2]) / utmax for k in ref)
    print("%s floor: largest relative differences fix - numpy %s" % (floor, worst))
    for name, value in worst.items():
        assert value <= 1e-8, (name, value)
    # the drive reaches the contacts: every factor reduced, the wall's too
    assert all(got[k][5] < 0.999 for k in got), got
    hist = local_rows(str(tmp_path / "pair.history"), 7)
    for k in hist:
        assert hist[k][6] == 1.0 - got[k][5], k
    if floor == "primitive":
        wall = atom_rows(str(tmp_path / "wall.history"))
        assert wall[1][3] == 1.0 - got[(0, 1)][5]
        assert all(wall[i][3] == 0.0 for i in range(2, N + 1))
    else:
        mesh = mesh_rows(str(tmp_path / "mesh.history"))
        # one contact with the mesh (the grain is on one triangle's face)
        assert len(mesh) == 1, mesh
        assert mesh[0][6] == 1.0 - got[(0, 1)][5]


def test_clamped_walls(tmp_path, lig):
    """a grain source with the floor clamped: the floor contact is a spring
    to a still node (the other engine-free cases are in the column test)"""
    walls = PRIMITIVE
    fix = ("group top id 5\n" + FIX.format(f=F, U0=U0, source="top", E=E, NU=NU,
                                          extra="direction 0.3 0 1"))
    run(lig, str(tmp_path), deck(walls, None, fix=fix))
    got = local_rows(str(tmp_path / "fix.contacts"), 6)
    assert (0, 1) in got and got[(0, 1)][4] > 0.0 and got[(0, 1)][5] < 1.0


# --------------------------------------------------------------------------
# 2. restart of the factors

@pytest.mark.parametrize("floor", ["primitive", "mesh"])
def test_restart(tmp_path, lig, floor):
    if floor == "primitive":
        walls, source = PRIMITIVE + "\n" + WALL_HISTORY, "wall floor"
    else:
        walls, source = MESH + "\n" + MESH_HISTORY, "mesh stl"
    first = deck(walls, source, "direction 0.3 0 1",
                 after="fix integr all nve/sphere\nrun 20\nwrite_restart state.restart")
    run(lig, str(tmp_path), first)
    factors = local_rows(str(tmp_path / "pair.history"), 7)
    assert min(row[6] for row in factors.values()) > 0.0
    if floor == "primitive":
        wall = atom_rows(str(tmp_path / "wall.history"))
        assert wall[1][3] > 0.0
    else:
        wall = mesh_rows(str(tmp_path / "mesh.history"))
        assert len(wall) == 1 and wall[0][6] > 0.0
    # a new run from the restart file, without the fix: the histories as they were
    second = deck(walls, None, fix="", read="read_restart state.restart", after="run 0")
    second = "\n".join(l for l in second.split("\n")
                       if "f_us" not in l and not l.startswith("dump_modify c "))
    d2 = tmp_path / "second"
    os.makedirs(str(d2))
    shutil.copy(str(tmp_path / "state.restart"), str(d2 / "state.restart"))
    run(lig, str(d2), second)
    again = local_rows(str(d2 / "pair.history"), 7)
    assert sorted(again) == sorted(factors)
    for k in factors:
        assert again[k][6] == factors[k][6], k
    if floor == "primitive":
        wall2 = atom_rows(str(d2 / "wall.history"))
    else:
        wall2 = mesh_rows(str(d2 / "mesh.history"))
    assert wall2 == wall


# --------------------------------------------------------------------------
# 3. bad inputs

BAD = [
    ("unknown wall", PRIMITIVE, "wall nowhere", "", "no wall 'nowhere'"),
    ("unknown mesh", MESH, "mesh nowhere", "", "no mesh 'nowhere'"),
    ("mesh without direction", MESH, "mesh stl", "", "give the drive with keyword direction"),
    ("mesh as wall", MESH, "wall stl", "direction 0 0 1", "write 'source mesh stl'"),
    ("wall as mesh", PRIMITIVE, "mesh floor", "", "write 'source wall floor'"),
    ("wall without ID", PRIMITIVE, "wall", None, "needs the ID of a fix"),
    ("wall fix not acoustic hooke", PRIMITIVE.replace("hertz", "hooke"), "wall floor", "",
     "is not model hertz"),
]


@pytest.mark.parametrize("nranks", [1, 2])
@pytest.mark.parametrize("name,walls,source,extra,message", BAD, ids=[b[0] for b in BAD])
def test_bad_input(tmp_path, lig, name, walls, source, extra, message, nranks):
    if extra is None:
        fix = "fix us all acoustic/mindlin 1 frequency 3000 amplitude 1e-5 source wall"
    else:
        fix = FIX.format(f=F, U0=U0, source=source, E=E, NU=NU, extra=extra)
    proc = run(lig, str(tmp_path), deck(walls, source, fix=fix), nranks=nranks,
               expect_error=True)
    errors = [line for line in proc.stdout.split("\n") if line.startswith("ERROR")]
    assert errors, proc.stdout[-2000:]
    assert "fix acoustic/mindlin" in errors[0], errors[0]
    assert message in errors[0], errors[0]


def test_fix_before_mesh_wall(tmp_path, lig):
    """the mesh's neighbor list and tracker must be updated before the fix"""
    fix = FIX.format(f=F, U0=U0, source="mesh stl", E=E, NU=NU, extra="direction 0 0 1")
    text = deck("", None, fix=fix).replace(fix, "fix stl all mesh/surface file floor.stl type 1\n"
                                           + fix + "\n" + MESH.split("\n")[1])
    proc = run(lig, str(tmp_path), text, expect_error=True)
    errors = [line for line in proc.stdout.split("\n") if line.startswith("ERROR")]
    assert errors, proc.stdout[-2000:]
    assert "define it after fix floor" in errors[0], errors[0]


# --------------------------------------------------------------------------
# 4. a run: the column under gravity on the vibrating floor, factors every 10
#    steps; the mesh floor gives the primitive floor's run, 2 ranks 1 rank's

DYNAMICS = ("fix grav all gravity 9.81 vector 0.2 0.0 -1.0\n"
            "fix integr all nve/sphere\n"
            "run 300\n"
            "dump d all custom 1 atoms.dump id x y z vx vy vz\n"
            "dump_modify d sort id format \"%d %.17g %.17g %.17g %.17g %.17g %.17g\"\n"
            "run 0")


def test_run_mesh_primitive_ranks(tmp_path, lig):
    states, rows = {}, {}
    for floor, nranks in (("primitive", 1), ("mesh", 1), ("mesh", 2)):
        if floor == "primitive":
            walls, source = PRIMITIVE, "wall floor"
        else:
            walls, source = MESH + "\n" + MESH_HISTORY, "mesh stl"
        fix = FIX.format(f=F, U0=U0, source=source, E=E, NU=NU,
                         extra="direction 0 0 1").replace("mindlin 1 ", "mindlin 10 ")
        text = deck(walls, source, fix=fix, after=DYNAMICS)
        text = text.replace("dump c all local 1", "dump c all local 10").replace(
            "dump h all local 1", "dump h all local 10").replace(
            "dump m all local 1", "dump m all local 10")
        d = tmp_path / ("%s_np%d" % (floor, nranks))
        run(lig, str(d), text, nranks=nranks)
        states[floor, nranks] = atom_rows(str(d / "atoms.dump"))
        rows[floor, nranks] = local_rows(str(d / "fix.contacts"), 6)
    a, b, c = states["primitive", 1], states["mesh", 1], states["mesh", 2]
    # the run did something: the grains moved down and sideways
    assert all(a[i][3] != 0.0 for i in a)
    assert c == b
    assert rows["mesh", 2] == rows["mesh", 1]
    worst = max(relative(a[i][k], b[i][k]) for i in a for k in range(3))
    worstv = max(abs(a[i][k] - b[i][k]) for i in a for k in range(3, 6)) / \
        max(abs(a[i][k]) for i in a for k in range(3, 6))
    print("mesh - primitive floor after 300 steps: positions %g, velocities %g" % (worst, worstv))
    assert worst < 1e-10 and worstv < 1e-6
    ra, rb = rows["primitive", 1], rows["mesh", 1]
    assert sorted(ra) == sorted(rb)
    assert max(relative(ra[k][5], rb[k][5]) for k in ra) < 1e-6
    assert min(row[5] for row in rb.values()) < 1.0
