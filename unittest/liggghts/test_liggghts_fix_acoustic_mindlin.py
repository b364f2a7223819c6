"""LIGGGHTS front end: fix acoustic/mindlin (liggghts/src/fix_acoustic_mindlin.*).

1. One packing, two engines: a frozen packing (64 grains of d ~ 1 mm on a
   perturbed simple-cubic lattice, overlaps 1-5 % of d, the 16 grains of the
   bottom layer the source group) written as a data file is read by LAMMPS
   (pair_style granular hertz/material + tangential linear_history/acoustic,
   the LAMMPS fix acoustic/mindlin) and by LIGGGHTS (pair_style gran model
   hertz tangential history/acoustic, this fix), with the same f, U0, source,
   stiffness hertz E nu, model full (and model normal, mode normal, an
   oblique direction with cmu, mu_min, ratio, kappa_scale); after run 0
   every contact (matched by
   its pair of atom IDs) has the same F_n, k_n, U_t and s in both engines'
   local outputs to 1e-10 relative, and the factor in LIGGGHTS's contact
   history (compute pair/gran/local ... history, last column 1 - s) is the
   fix's s.
2. The factors change the dynamics: the packing released (nve/sphere,
   gravity, 100 steps of 1 us, factors every 10: the overlapping packing
   expands, most contacts still closed at the end) ends elsewhere with U0 > 0 than
   with U0 = 0; with f = 0 every factor is 1 and the run is bitwise the run
   without the fix.
3. 1 and 2 MPI ranks give the same factors (1e-12), frozen and after the
   dynamic run.
4. Bad inputs stop LIGGGHTS with an ERROR line naming the problem.

Needs ACOUSTIC_LIGGGHTS (lmp_acoustic) and ACOUSTIC_LMP (LAMMPS with the
ACOUSTIC package), and mpirun for the 2-rank runs."""
import math
import os
import shutil
import subprocess

import pytest

E, NU, MU = 1e7, 0.3, 0.5
D = 1e-3
NSIDE, NLAYERS = 4, 4
NSOURCE = NSIDE * NSIDE          # the bottom layer: atom IDs 1..16
NCONTACTS = 3 * NSIDE * NSIDE * (NSIDE - 1)

LIGGGHTS_DECK = """\
atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
processors * 1 1
units si
read_data packing.data
neighbor 2e-4 bin
neigh_modify delay 0
fix m1 all property/global youngsModulus peratomtype {E}
fix m2 all property/global poissonsRatio peratomtype {NU}
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.5
fix m4 all property/global coefficientFriction peratomtypepair 1 {MU}
fix m5 all property/global characteristicVelocity scalar 1.0
pair_style gran model {normal} tangential {tangential}
pair_coeff * *
timestep 1e-6
group src id <> 1 {NSOURCE}
group free subtract all src
{fix}
{outputs}
{run}
"""

LIGGGHTS_FIX = ("fix us all acoustic/mindlin {N} frequency {f} amplitude {U0} source src "
                "stiffness hertz {E} {NU} model full {extra}")

# LIGGGHTS wants compute pair/gran/local before the first run
LIGGGHTS_COMPUTES = """\
compute pgl all pair/gran/local id history
thermo_style custom step atoms f_us[1] f_us[2] f_us[3]
thermo_modify format float %.17g
"""

LIGGGHTS_OUTPUTS = """\
dump c all local {N} fix.contacts f_us[1] f_us[2] f_us[3] f_us[4] f_us[5] f_us[6]
dump_modify c format "%.17g %.17g %.17g %.17g %.17g %.17g"
dump h all local {N} pair.history c_pgl[1] c_pgl[2] c_pgl[3] c_pgl[4] c_pgl[5] c_pgl[6] c_pgl[7]
dump_modify h format "%.17g %.17g %.17g %.17g %.17g %.17g %.17g"
"""

LIGGGHTS_DYNAMICS = """\
fix grav free gravity 9.81 vector 0.3 0.0 -1.0
fix integr free nve/sphere
run 100
dump d all custom 1 atoms.dump id x y z vx vy vz omegax omegay omegaz
dump_modify d sort id format "%d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g"
{outputs}
run 0
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
fix us all acoustic/mindlin 1 frequency {f} amplitude {U0} source src stiffness hertz {E} {NU} model full {extra}
thermo_style custom step atoms f_us[1] f_us[2] f_us[3]
dump c all local 1 fix.contacts f_us[1] f_us[2] f_us[3] f_us[4] f_us[5] f_us[6]
dump_modify c format float %.17g
run 0
"""


def executable(name, what):
    exe = os.environ.get(name)
    if not exe:
        pytest.fail("%s is not set: set it to %s" % (name, what))
    if not (os.path.isfile(exe) and os.access(exe, os.X_OK)):
        pytest.fail("%s=%s is not an executable file" % (name, exe))
    return os.path.abspath(exe)


def run_env():
    env = dict(os.environ)
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    env.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")
    env.setdefault("OMPI_MCA_mpi_yield_when_idle", "1")
    return env


def write_packing(directory):
    """64 grains on a perturbed simple-cubic lattice of spacing 0.97 d, each
    touching its 6 lattice neighbours (no diagonal contact), deterministic."""
    spacing = 0.97 * D
    lines = []
    n = 0
    for k in range(NLAYERS):
        for j in range(NSIDE):
            for i in range(NSIDE):
                n += 1
                d = D * (1 + 0.01 * math.sin(2.3 * n))
                x = i * spacing + 0.004 * D * math.sin(1.7 * n)
                y = j * spacing + 0.004 * D * math.cos(3.1 * n)
                z = D / 2 + k * spacing + 0.004 * D * math.sin(0.9 * n + 1)
                lines.append("%d 1 %.17g 2500 %.17g %.17g %.17g" % (n, d, x, y, z))
    lo, hi = -D, NSIDE * D + D
    with open(os.path.join(directory, "packing.data"), "w") as f:
        f.write("frozen packing\n\n%d atoms\n1 atom types\n\n" % n)
        f.write("%.17g %.17g xlo xhi\n%.17g %.17g ylo yhi\n%.17g %.17g zlo zhi\n\n"
                % (lo, hi, lo, hi, lo, NLAYERS * D + 2 * D))
        f.write("Atoms\n\n" + "\n".join(lines) + "\n")


def run(exe, directory, deck, nranks=1, expect_error=False):
    os.makedirs(directory, exist_ok=True)
    write_packing(directory)
    with open(os.path.join(directory, "in.deck"), "w") as f:
        f.write(deck)
    cmd = [exe, "-in", "in.deck", "-log", "log.txt", "-echo", "log"]
    if nranks > 1:
        mpirun = shutil.which("mpirun")
        if mpirun is None:
            pytest.fail("mpirun is not on PATH (needed for the %d-rank runs)" % nranks)
        cmd = [mpirun, "-np", str(nranks)] + cmd
    proc = subprocess.run(cmd, cwd=directory, env=run_env(), stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, universal_newlines=True, errors="replace",
                          timeout=600)
    if expect_error:
        return proc
    if proc.returncode != 0 or "ERROR" in proc.stdout:
        pytest.fail("run failed (%s) in %s:\n%s" % (proc.returncode, directory, proc.stdout[-3000:]))
    return proc


def liggghts_deck(f, U0, N=1, normal="hertz", tangential="history/acoustic", fix=None,
                  dynamics=False, outputs=True, extra=""):
    if fix is None:
        fix = LIGGGHTS_FIX.format(N=N, f=f, U0=U0, E=E, NU=NU, extra=extra)
    computes = LIGGGHTS_COMPUTES if (fix and outputs) else ""
    # a dump of the fix's local rows must come at multiples of N
    outputs = LIGGGHTS_OUTPUTS.format(N=N) if (fix and outputs) else ""
    if dynamics:
        # the dumps after the run: the state and the factors at its end
        return LIGGGHTS_DECK.format(E=E, NU=NU, MU=MU, NSOURCE=NSOURCE, normal=normal,
                                    tangential=tangential, fix=fix, outputs=computes,
                                    run=LIGGGHTS_DYNAMICS.format(outputs=outputs))
    return LIGGGHTS_DECK.format(E=E, NU=NU, MU=MU, NSOURCE=NSOURCE, normal=normal,
                                tangential=tangential, fix=fix, outputs=computes + outputs,
                                run="run 0")


def local_rows(path, ncols):
    """the last snapshot of a dump local: {(lower ID, higher ID): row}"""
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


def relative(x, y):
    if x == y:
        return 0.0
    return abs(x - y) / max(abs(x), abs(y))


@pytest.fixture(scope="module")
def exes():
    return (executable("ACOUSTIC_LIGGGHTS", "the LIGGGHTS executable lmp_acoustic"),
            executable("ACOUSTIC_LMP", "the LAMMPS executable with the ACOUSTIC package"))


# --------------------------------------------------------------------------
# 1. one packing, two engines

# the keywords after model full (a later "model" wins in both engines)
@pytest.mark.parametrize("f,U0,extra", [
    (3000.0, 1e-5, ""), (3000.0, 1e-4, ""), (1000.0, 1e-5, ""),
    (3000.0, 1e-4, "model normal"),
    (3000.0, 1e-4, "mode normal"),
    (3000.0, 1e-4, "direction 1 0 1 cmu 0.5 mu_min 0.2 ratio 0.5 kappa_scale 0.3")])
def test_same_factors_as_lammps(tmp_path, exes, f, U0, extra):
    lig, lmp = exes
    run(lig, str(tmp_path / "liggghts"), liggghts_deck(f, U0, extra=extra))
    run(lmp, str(tmp_path / "lammps"),
        LAMMPS_DECK.format(E=E, NU=NU, MU=MU, NSOURCE=NSOURCE, f=f, U0=U0, extra=extra))
    a = local_rows(str(tmp_path / "liggghts" / "fix.contacts"), 6)
    b = local_rows(str(tmp_path / "lammps" / "fix.contacts"), 6)
    assert len(a) == NCONTACTS
    assert sorted(a) == sorted(b)
    worst = {}
    for name, col in (("F_n", 2), ("k_n", 3), ("U_t", 4), ("s", 5)):
        worst[name] = max(relative(a[k][col], b[k][col]) for k in a)
    print("f = %g, U0 = %g %s: largest relative differences LIGGGHTS - LAMMPS %s"
          % (f, U0, extra, worst))
    for name, value in worst.items():
        assert value <= 1e-10, (name, value)
    # the drive reached the contacts: a range of factors, U_t > 0 off the source layer
    factors = [row[5] for row in a.values()]
    assert min(factors) < 0.99
    assert all(a[k][4] > 0.0 for k in a if k[1] > NSOURCE)
    if "mode normal" not in extra:
        # mode all: the source grains move as one, their contacts do not slip
        assert all(a[k][4] == 0.0 and a[k][5] == 1.0 for k in a if k[1] <= NSOURCE)
    # the contact history holds 1 - s of the fix's row, bit for bit
    hist = local_rows(str(tmp_path / "liggghts" / "pair.history"), 7)
    assert sorted(hist) == sorted(a)
    for k in a:
        assert hist[k][6] == 1.0 - a[k][5], k
    # the global vector: contacts, mean and min factor
    log = open(str(tmp_path / "liggghts" / "log.txt")).read().split("\n")
    header = [i for i, line in enumerate(log) if line.split()[:2] == ["Step", "Atoms"]][0]
    values = [float(t) for t in log[header + 1].split()]
    assert values[2] == NCONTACTS
    assert relative(values[3], sum(factors) / len(factors)) < 1e-14
    # read back from the histories, as the LAMMPS fix does: 1 - (1 - s)
    assert values[4] == min(1.0 - (1.0 - x) for x in factors)


# --------------------------------------------------------------------------
# 2. the factors change the dynamics; f = 0 is the plain run bit for bit

def final_state(directory):
    with open(os.path.join(directory, "atoms.dump")) as f:
        return f.read().split("ITEM: ATOMS")[-1]


def test_factors_change_dynamics(tmp_path, exes):
    lig = exes[0]
    runs = {"vibrated": liggghts_deck(3000.0, 1e-4, N=10, dynamics=True),
            "still": liggghts_deck(3000.0, 0.0, N=10, dynamics=True),
            "f0": liggghts_deck(0.0, 1e-4, N=10, dynamics=True),
            "plain": liggghts_deck(0.0, 0.0, fix="", dynamics=True)}
    states = {}
    for name, deck in runs.items():
        run(lig, str(tmp_path / name), deck)
        states[name] = final_state(str(tmp_path / name))
    assert states["vibrated"] != states["still"]
    assert states["f0"] == states["plain"]
    assert states["still"] == states["plain"]
    f0 = local_rows(str(tmp_path / "f0" / "fix.contacts"), 6)
    assert f0 and all(row[5] == 1.0 and row[4] == 0.0 for row in f0.values())
    vib = local_rows(str(tmp_path / "vibrated" / "fix.contacts"), 6)
    assert min(row[5] for row in vib.values()) < 0.99


# --------------------------------------------------------------------------
# 3. 1 and 2 ranks

@pytest.mark.parametrize("dynamics", [False, True])
def test_one_and_two_ranks(tmp_path, exes, dynamics):
    lig = exes[0]
    rows = {}
    for nranks in (1, 2):
        d = str(tmp_path / ("np%d" % nranks))
        proc = run(lig, d, liggghts_deck(3000.0, 1e-4, N=10, dynamics=dynamics), nranks=nranks)
        assert ("1 by 1 by 1" if nranks == 1 else "2 by 1 by 1") in proc.stdout
        if nranks == 2:
            # contacts across the two ranks: ghost atoms
            nghost = [l for l in proc.stdout.split("\n") if l.startswith("Nghost:")]
            assert nghost and float(nghost[-1].split()[1]) > 0, nghost
        rows[nranks] = (local_rows(os.path.join(d, "fix.contacts"), 6),
                        local_rows(os.path.join(d, "pair.history"), 7))
    (a, ha), (b, hb) = rows[1], rows[2]
    assert len(a) > 0 and sorted(a) == sorted(b)
    worst = max(relative(a[k][c], b[k][c]) for k in a for c in (2, 3, 4, 5))
    print("dynamics %s: largest relative difference 1 - 2 ranks %g" % (dynamics, worst))
    assert worst <= 1e-12
    # each contact's history value is that of its row, on whichever rank
    assert sorted(hb) == sorted(b)
    for k in b:
        assert hb[k][6] == 1.0 - b[k][5]


# --------------------------------------------------------------------------
# 4. bad inputs

FIX = "fix us all acoustic/mindlin 1 frequency 3000 amplitude 1e-4 source src "
BAD = [
    ("unknown keyword", FIX + "stiffness hertz 1e7 0.3 bogus 1", None, "unknown keyword 'bogus'"),
    ("negative frequency", FIX.replace("3000", "-1") + "stiffness hertz 1e7 0.3", None,
     "keyword frequency"),
    ("bad amplitude", FIX.replace("1e-4", "abc") + "stiffness hertz 1e7 0.3", None,
     "keyword amplitude"),
    ("bad N", FIX.replace("mindlin 1 ", "mindlin 0 ") + "stiffness hertz 1e7 0.3", None,
     "N must be a positive integer"),
    ("no stiffness", FIX, None, "stiffness hertz E nu is required"),
    ("stiffness pair", FIX + "stiffness pair", None, "only 'hertz E nu'"),
    ("bad nu", FIX + "stiffness hertz 1e7 0.7", None, "-1 < nu < 0.5"),
    ("bad mode", FIX + "stiffness hertz 1e7 0.3 mode sideways", None, "mode must be"),
    ("bad model", FIX + "stiffness hertz 1e7 0.3 model half", None, "model must be"),
    ("bad mu_min", FIX + "stiffness hertz 1e7 0.3 mu_min 2", None, "mu_min must be in [0, 1]"),
    ("missing value", FIX + "stiffness hertz 1e7 0.3 cmu", None, "keyword cmu needs 1 value"),
    ("mode normal oblique", FIX + "stiffness hertz 1e7 0.3 mode normal direction 1 0 1", None,
     "give a direction along x, y or z"),
    ("no source group", FIX.replace("source src", "source nowhere") + "stiffness hertz 1e7 0.3",
     None, "no group 'nowhere'"),
    ("empty source group", FIX.replace("source src", "source empty") + "stiffness hertz 1e7 0.3",
     None, "group empty has no atoms"),
    ("tangential history", FIX + "stiffness hertz 1e7 0.3", ("hertz", "history"),
     "no acoustic history value"),
    ("hooke", FIX + "stiffness hertz 1e7 0.3", ("hooke", "history/acoustic"),
     "needs pair_style gran model hertz"),
    ("pair none", FIX + "stiffness hertz 1e7 0.3", "none", "needs pair_style gran"),
]


@pytest.mark.parametrize("name,fix,models,message", BAD, ids=[b[0] for b in BAD])
def test_bad_input(tmp_path, exes, name, fix, models, message):
    lig = exes[0]
    if "source empty" in fix:
        fix = "region nothing block 1 2 1 2 1 2 units box\ngroup empty region nothing\n" + fix
    if models == "none":
        deck = liggghts_deck(0, 0, fix=fix, outputs=False).replace(
            "pair_style gran model hertz tangential history/acoustic\npair_coeff * *",
            "pair_style none")
    else:
        normal, tangential = models or ("hertz", "history/acoustic")
        deck = liggghts_deck(0, 0, normal=normal, tangential=tangential, fix=fix, outputs=False)
    proc = run(lig, str(tmp_path), deck, expect_error=True)
    errors = [line for line in proc.stdout.split("\n") if line.startswith("ERROR")]
    assert errors, proc.stdout[-2000:]
    assert "fix acoustic/mindlin" in errors[0], errors[0]
    assert message in errors[0], errors[0]
