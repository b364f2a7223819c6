"""LIGGGHTS front end: "tangential history/acoustic" with no fix setting the
friction factor (s = 1 on every contact, the value a new contact starts at)
gives the run of "tangential history" bit for bit.

Each case is a real run of in.bitwise_history (about 200 grains falling on an
STL ramp, a mesh wall, and a primitive floor under a tilted gravity, 20 000
steps) by the LIGGGHTS executable named by ACOUSTIC_LIGGGHTS, on 1 and 2 MPI
ranks, with the normal models hertz and hooke.  The final dump (id x y z v f
omega radius at %.17g, sorted by id) of history/acoustic must equal that of
history byte for byte and float for float.

The runs must also have exercised the model: contacts in the thermo output,
grains on the floor and on the ramp, and the Coulomb limit reached by
grain-grain, grain-floor and grain-ramp contacts (a rerun with that
coefficientFriction at 1000 differs: had no such contact ever reached
mu |F_n|, a larger mu could not change a bit of the run).  The contact
history of history/acoustic has exactly one value more than that of history,
in the pair style, the mesh wall and the primitive floor, and it is 0
(s = 1) on every contact.

LIGGGHTS refuses "newton on" (pair) with any history model: the test checks
that both models are refused alike.

Needs: ACOUSTIC_LIGGGHTS=<path of lmp_acoustic>, and mpirun (Open MPI) on
PATH for the 2-rank runs."""
import os
import re
import shutil
import subprocess

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
DECK = os.path.join(HERE, "in.bitwise_history")
STL = os.path.join(HERE, "ramp.stl")

NORMALS = ["hertz", "hooke"]
RANKS = [1, 2]
NATOMS = 192
NHIST = {"history": 3, "history/acoustic": 4}   # shearx, sheary, shearz (+ 1 - s)
NCOLS_ID_FORCES = 9                              # id (3), force_normal, force_tangential


def liggghts():
    exe = os.environ.get("ACOUSTIC_LIGGGHTS")
    if not exe:
        pytest.fail("ACOUSTIC_LIGGGHTS is not set: set it to the LIGGGHTS executable "
                    "built with the ACOUSTIC tangential model (lmp_acoustic)")
    if not (os.path.isfile(exe) and os.access(exe, os.X_OK)):
        pytest.fail("ACOUSTIC_LIGGGHTS=%s is not an executable file" % exe)
    return os.path.abspath(exe)


def run_env():
    env = dict(os.environ)
    # Open MPI as root, more ranks than free cores, and no busy waiting on
    # a loaded machine (a 2-rank run is 3x slower with it)
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    env.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")
    env.setdefault("OMPI_MCA_mpi_yield_when_idle", "1")
    return env


class Run:
    """One run of the deck in a directory of its own."""

    def __init__(self, workdir, nranks, variables):
        self.dir = workdir
        self.prefix = "out"
        cmd = [liggghts(), "-in", DECK, "-log", "log.liggghts", "-echo", "log",
               "-var", "stl", STL, "-var", "prefix", self.prefix]
        for name, value in sorted(variables.items()):
            cmd += ["-var", name, str(value)]
        if nranks > 1:
            mpirun = shutil.which("mpirun")
            if mpirun is None:
                pytest.fail("mpirun is not on PATH (needed for the %d-rank runs)" % nranks)
            cmd = [mpirun, "-np", str(nranks)] + cmd
        self.cmd = cmd
        proc = subprocess.run(cmd, cwd=workdir, env=run_env(), stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, timeout=600)
        self.returncode = proc.returncode
        self.output = proc.stdout.decode("utf-8", "replace")
        logfile = os.path.join(workdir, "log.liggghts")
        self.log = ""
        if os.path.exists(logfile):
            with open(logfile, "rb") as f:
                self.log = f.read().decode("utf-8", "replace")

    def describe(self):
        return "%s\n(in %s)\n--- last output ---\n%s" % (
            " ".join(self.cmd), self.dir, "\n".join(self.output.splitlines()[-25:]))

    def check_ok(self):
        assert self.returncode == 0 and "ERROR" not in self.output, \
            "the run failed:\n" + self.describe()
        return self

    def path(self, ext):
        return os.path.join(self.dir, "%s.%s" % (self.prefix, ext))

    def text(self, ext):
        with open(self.path(ext), "rb") as f:
            return f.read()

    def rows(self, ext):
        """The rows after the ITEM: ATOMS / ITEM: ENTRIES line, as float lists."""
        lines = self.text(ext).decode().splitlines()
        start = [i for i, l in enumerate(lines) if l.startswith(("ITEM: ATOMS", "ITEM: ENTRIES"))]
        assert len(start) == 1, "%s: expected one snapshot" % self.path(ext)
        return [[float(x) for x in l.split()] for l in lines[start[0] + 1:] if l.strip()]

    def thermo(self):
        """The rows of the thermo table of the main run (step atoms ke ncsum)."""
        rows = []
        table = False
        for line in self.log.splitlines():
            if re.match(r"\s*Step\s+Atoms\s+KinEng\s+ncsum", line):
                table = True
                continue
            if table:
                if re.match(r"\s*\d+\s", line):
                    rows.append(line.split())
                else:
                    table = False
        return rows


_runs = {}


@pytest.fixture(scope="module")
def deck_run(tmp_path_factory):
    """deck_run(nranks, normal=..., tangential=..., ...) -> Run, each distinct run once."""
    liggghts()

    def get(nranks, **variables):
        key = (nranks, tuple(sorted(variables.items())))
        if key not in _runs:
            name = "np%d_" % nranks + "_".join(
                "%s-%s" % (k, str(v).replace("/", "-")) for k, v in sorted(variables.items()))
            _runs[key] = Run(str(tmp_path_factory.mktemp(name)), nranks, variables)
        return _runs[key]
    return get


def reference_runs(deck_run, normal, nranks):
    h = deck_run(nranks, normal=normal, tangential="history", nhist=NHIST["history"]).check_ok()
    a = deck_run(nranks, normal=normal, tangential="history/acoustic",
                 nhist=NHIST["history/acoustic"]).check_ok()
    return h, a


def first_difference(text_a, text_b):
    la, lb = text_a.splitlines(), text_b.splitlines()
    for i, (x, y) in enumerate(zip(la, lb)):
        if x != y:
            return "line %d:\n  history:          %s\n  history/acoustic: %s" % (i + 1, x, y)
    return "same lines up to line %d, then %d against %d lines" % (min(len(la), len(lb)), len(la), len(lb))


@pytest.mark.parametrize("nranks", RANKS)
@pytest.mark.parametrize("normal", NORMALS)
def test_history_acoustic_is_bitwise_history(deck_run, normal, nranks):
    h, a = reference_runs(deck_run, normal, nranks)
    th, ta = h.text("dump"), a.text("dump")
    assert th == ta, "the final dumps differ at " + first_difference(th.decode(), ta.decode())
    rh, ra = h.rows("dump"), a.rows("dump")
    assert len(rh) == NATOMS and all(len(r) == 14 for r in rh)
    assert [r[0] for r in rh] == list(range(1, NATOMS + 1)), "the dump is not sorted by id"
    assert all(v == v for r in rh for v in r), "NaN in the dump"
    assert rh == ra
    # and the whole way there: the thermo tables (step, atoms, ke, contacts;
    # 21 rows of the run and the one of the closing "run 0")
    assert h.thermo() == a.thermo() and len(h.thermo()) == 22


@pytest.mark.parametrize("nranks", RANKS)
@pytest.mark.parametrize("normal", NORMALS)
def test_runs_exercise_walls_and_contacts(deck_run, normal, nranks):
    h, _ = reference_runs(deck_run, normal, nranks)
    thermo = h.thermo()
    assert all(int(r[1]) == NATOMS for r in thermo), "grains were lost"
    ncontacts = [float(r[3]) for r in thermo]
    assert ncontacts[0] == 0 and ncontacts[-1] >= 400, \
        "contact counts (sum of contact/atom): %s" % ncontacts
    assert float(thermo[-1][2]) < 1e-3 * max(float(r[2]) for r in thermo), "the grains did not settle"
    atoms = h.rows("dump")
    on_floor = [r for r in atoms if r[3] < r[13]]        # z < radius: overlaps the floor z = 0
    assert len(on_floor) >= 20, "%d grains on the primitive floor" % len(on_floor)
    on_ramp = h.rows("wall")
    assert len(on_ramp) >= 1, "no grain on the STL ramp at the end"
    assert len(h.rows("pair")) * 2 == ncontacts[-1]
    # on 2 ranks the box is split across the pile (processors 1 * 1): both
    # ranks hold grains and see the other's as ghosts
    assert "1 by %d by 1 MPI processor grid" % nranks in h.log
    if nranks > 1:
        nlocal_min = [float(m) for m in re.findall(r"^Nlocal:.* ([-0-9.e+]+) min$", h.log, re.M)]
        nghost_min = [float(m) for m in re.findall(r"^Nghost:.* ([-0-9.e+]+) min$", h.log, re.M)]
        assert nlocal_min and min(nlocal_min) >= 40, "grains per rank: %s" % nlocal_min
        assert nghost_min and min(nghost_min) > 0, "ghost grains per rank: %s" % nghost_min


@pytest.mark.parametrize("contacts", ["mu", "muw", "mum"])
@pytest.mark.parametrize("normal", NORMALS)
def test_coulomb_limit_is_reached(deck_run, normal, contacts):
    """The friction coefficient enters the history model only through the
    Coulomb limit: had no contact reached it, a larger one would change
    nothing.  mu: grain-grain, muw: grain-primitive wall, mum: grain-mesh."""
    h, _ = reference_runs(deck_run, normal, 1)
    sticky = deck_run(1, normal=normal, tangential="history", nhist=NHIST["history"],
                      **{contacts: 1000}).check_ok()
    assert h.text("dump") != sticky.text("dump"), \
        "%s 0.3 and 1000 give the same run: no contact reached the Coulomb limit" % contacts


# the dumps of contact history: (extension, description, leading columns)
HISTORY_DUMPS = [
    ("pair", "pair contacts", NCOLS_ID_FORCES),
    ("wall", "mesh-wall contacts", NCOLS_ID_FORCES),
    ("floor", "floor (primitive wall) history of each grain", 1),
]


@pytest.mark.parametrize("nranks", RANKS)
@pytest.mark.parametrize("normal", NORMALS)
def test_one_more_history_value_and_it_is_zero(deck_run, normal, nranks):
    """history/acoustic adds its value after the three of history (its
    history model registers first): the last column, 1 - s, is 0 everywhere
    and without it the dump is that of history, bit for bit."""
    h, a = reference_runs(deck_run, normal, nranks)
    for ext, what, lead in HISTORY_DUMPS:
        rows_h, rows_a = h.rows(ext), a.rows(ext)
        assert len(rows_h) == len(rows_a) > 0, "%s: %d and %d rows" % (what, len(rows_h), len(rows_a))
        assert all(len(r) == lead + NHIST["history"] for r in rows_h), what
        assert all(len(r) == lead + NHIST["history/acoustic"] for r in rows_a), what
        assert [r[:-1] for r in rows_a] == rows_h, \
            "%s: history/acoustic without its last column is not history" % what
        values = [r[-1] for r in rows_a]
        assert all(v == 0.0 for v in values), \
            "%s: acousticFrictionReduction (1 - s) not 0 everywhere: %s" % (what, values[:10])
        # the other columns hold real shear history
        assert any(r[lead] != 0.0 for r in rows_h), "%s: no shear history" % what
    assert len(h.rows("floor")) == NATOMS


@pytest.mark.parametrize("normal", NORMALS)
@pytest.mark.parametrize("tangential", ["history", "history/acoustic"])
@pytest.mark.parametrize("where", ["pair", "wall", "floor"])
def test_no_further_history_value(deck_run, normal, tangential, where):
    """One history column more than NHIST is refused, in the pair, the mesh
    wall or the floor dump (the deck's nhist, nhistw, nhistf)."""
    n = NHIST[tangential]
    var = {"nhist": n, "nhistw": n, "nhistf": n}
    var[{"pair": "nhist", "wall": "nhistw", "floor": "nhistf"}[where]] = n + 1
    r = deck_run(1, normal=normal, tangential=tangential, nsteps=0, **var)
    assert r.returncode != 0, "a dump of %d %s history values was accepted" % (n + 1, where)
    assert re.search(r"ERROR: Dump (local compute|custom fix) vector is accessed out-of-range",
                     r.output), r.describe()
    dumps = [l.split()[1] for l in r.log.splitlines() if l.startswith("dump ")]
    assert dumps and dumps[-1] == where[0], r.describe()


@pytest.mark.parametrize("normal", NORMALS)
def test_newton_on_is_refused_alike(deck_run, normal):
    outputs = []
    for tangential in ("history", "history/acoustic"):
        r = deck_run(1, normal=normal, tangential=tangential, newton="on", nsteps=0,
                     nhist=NHIST[tangential])
        assert r.returncode != 0, "newton on was accepted:\n" + r.describe()
        assert "Pair granular with shear history requires newton pair off" in r.output, r.describe()
        outputs.append([l for l in r.output.splitlines() if l.startswith("ERROR")])
    assert outputs[0] == outputs[1]
