"""A tilt ramp of examples/avalanche run as pieces (run_ensemble.sh with
AVALANCHE_PIECE): every piece ends after a whole angle, the next one goes on
from that angle's restart, and the ramp reads as one -- the angles follow each
other without a gap or a repeat, the series and the dumps go forward in time,
the answer line is written once.  A piece killed in the middle of an angle
loses that angle only: what it wrote after the last whole angle is cut off
before the ramp goes on.  Every angle starts with a full set-up (neighbour
lists, forces), and a resumed piece keeps the friction factors of fix
acoustic/mindlin's last update (its restart state), so the pieced ramp is the
uninterrupted one bit for bit: the same angle lines, the same series data, the
same dumps of the grains and of the contacts' mu*/mu, at 0 Hz and at 70 kHz
(same deck), on 1 rank and on 2, with the layer at rest or flowing at the
boundary."""
import os
import re
import subprocess

import pytest

LMP = os.environ.get("ACOUSTIC_LMP", "lmp")
HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples", "avalanche")
ENSEMBLE = os.path.join(HERE, "run_ensemble.sh")
ANGLE = re.compile(r"^angle +([0-9.]+) deg: (\w+)")


def build_dir():
    return os.path.dirname(os.path.dirname(os.path.abspath(LMP)))


def run_ensemble(out, freq="0", theta0="16", ranks="1", **env):
    """One ramp of a small periodic layer (3 d thick, 20 d long)."""
    environ = dict(os.environ, AVALANCHE_OUT=str(out), AVALANCHE_NP=ranks, AVALANCHE_FREE="0",
                   AVALANCHE_LAYER="20", AVALANCHE_THETA0=theta0, **env)
    done = subprocess.run(["bash", ENSEMBLE, build_dir(), "3", "7", freq], env=environ,
                          capture_output=True, text=True, timeout=900)
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]
    return done.stdout


def angles(log):
    return [(float(m.group(1)), m.group(2)) for m in map(ANGLE.match, open(log)) if m]


def angle_lines(log):
    return [line for line in open(log) if ANGLE.match(line)]


def series_data(path):
    """The data lines of a series (each piece starts with its title line)."""
    return [line for line in open(path) if not line.startswith("#")]


def series_times(path):
    return [float(line.split()[0]) for line in open(path) if not line.startswith("#")]


def dump_steps(path):
    steps, lines = [], open(path).read().split("\n")
    for k, line in enumerate(lines):
        if line.startswith("ITEM: TIMESTEP"):
            steps.append(int(lines[k + 1]))
    return steps


@pytest.fixture(scope="module")
def whole(tmp_path_factory):
    out = tmp_path_factory.mktemp("whole")
    run_ensemble(out, AVALANCHE_PIECE="0")
    return out / "H3" / "s7"


@pytest.fixture(scope="module")
def pieced(tmp_path_factory, whole):
    out = tmp_path_factory.mktemp("pieced")
    # the same packing: the deposit is made by the first job of a packing
    os.makedirs(out / "H3" / "s7")
    for name in ("deposit.restart", "log.deposit"):
        (out / "H3" / "s7" / name).write_bytes((whole / name).read_bytes())
    said = run_ensemble(out, AVALANCHE_PIECE="0.2", AVALANCHE_MAXPIECES="1")
    path = out / "H3" / "s7"
    assert "paused after 1 piece" in said
    first = angle_lines(path / "log.f0")
    # a killed piece: output written past the last whole angle
    theta, tres, step, last, following = open(path / "f0.resume").read().split()
    assert float(following) == float(theta) + 0.5, "the next angle, one dtheta on"
    with open(path / "f0.series", "a") as f:
        f.write(f"{float(tres) + 0.0005:.4f} 99 0 0 0 0 0 0 0 0\n")
    with open(path / "f0.dump", "a") as f:
        f.write(f"ITEM: TIMESTEP\n{int(step) + 100}\nITEM: NUMBER OF ATOMS\n0\n")
    with open(path / "log.f0", "a") as f:
        f.write("(killed here)\n")
    said = run_ensemble(out, AVALANCHE_PIECE="0.2")
    return path, first, float(theta), said


def test_first_piece_is_the_uninterrupted_ramp(whole, pieced):
    path, first, theta, _ = pieced
    assert first and float(ANGLE.match(first[-1]).group(1)) == theta
    assert first == angle_lines(whole / "log.f0")[:len(first)]


def test_pieced_ramp_is_the_uninterrupted_one_bit_for_bit(whole, pieced):
    path = pieced[0]
    assert angle_lines(path / "log.f0") == angle_lines(whole / "log.f0")
    for name in ("f0.dump", "f0.contacts"):
        assert (path / name).read_bytes() == (whole / name).read_bytes(), name
    assert series_data(path / "f0.series") == series_data(whole / "f0.series")


def test_pieces_at_70_kHz_bit_for_bit(tmp_path, whole):
    """Two creeping angles (1.3 s each) as one process and as two pieces."""
    for sub in ("one", "two"):
        os.makedirs(tmp_path / sub / "H3" / "s7")
        for name in ("deposit.restart", "log.deposit"):
            (tmp_path / sub / "H3" / "s7" / name).write_bytes((whole / name).read_bytes())
    run_ensemble(tmp_path / "one", freq="70e3", theta0="12", AVALANCHE_PIECE="2.5", AVALANCHE_MAXPIECES="1")
    run_ensemble(tmp_path / "two", freq="70e3", theta0="12", AVALANCHE_PIECE="0.2", AVALANCHE_MAXPIECES="2")
    one, two = tmp_path / "one" / "H3" / "s7", tmp_path / "two" / "H3" / "s7"
    assert len(angle_lines(two / "log.f70")) == 2
    assert angle_lines(one / "log.f70") == angle_lines(two / "log.f70")
    assert "mean mu*/mu 1.000" not in angle_lines(two / "log.f70")[0], "the ultrasound lowers friction"
    for name in ("f70.dump", "f70.contacts"):
        assert (one / name).read_bytes() == (two / name).read_bytes(), name


def test_pieces_in_a_flowing_layer_on_2_ranks_bit_for_bit(tmp_path, whole):
    """At 70 kHz on 2 ranks, angles of 0.1 s (no follow-up time): the layer
    still flows at the end of the angles where the pieces pause.  Resumed
    pieces went on otherwise when fix acoustic/mindlin was defined after a
    run (its restart state dropped: a new solve at the set-up) and when they
    made set-ups of their own before the first angle's (each one rescales the
    tangential history of the sliding contacts)."""
    for sub in ("one", "two"):
        os.makedirs(tmp_path / sub / "H3" / "s7")
        for name in ("deposit.restart", "log.deposit"):
            (tmp_path / sub / "H3" / "s7" / name).write_bytes((whole / name).read_bytes())
    # from 14 deg the layer creeps after the pre-ramp and flows from about 17.5
    # deg; a start at 17 deg flowed uniformly at once on one machine (the path of
    # a 70 kHz ramp changes with the BLAS kernels), leaving no boundary to test
    flowing = dict(freq="70e3", theta0="14", ranks="2", AVALANCHE_TFOLLOW="0")
    run_ensemble(tmp_path / "one", AVALANCHE_PIECE="0", **flowing)
    said = run_ensemble(tmp_path / "two", AVALANCHE_PIECE="0.05", **flowing)
    one, two = tmp_path / "one" / "H3" / "s7", tmp_path / "two" / "H3" / "s7"
    states = angles(two / "log.f70")
    log = open(two / "log.f70").read()
    assert log.count("paused after") == len(states) - 1 >= 3, "a boundary after each angle"
    # (at least two boundaries where the layer moves fast, "local" with half of
    # the grains mobile or "partial": which of the two changes from machine to
    # machine)
    flows = [float(e) for e in re.findall(r"deg: (?:local|partial) .* max E_k/E_t (\S+)", log)]
    assert len([e for e in flows if e > 1e-3]) >= 2, "the layer flows at the boundaries"
    assert "Unused restart file" not in log, "fix us keeps its restart state"
    assert angle_lines(one / "log.f70") == angle_lines(two / "log.f70")
    for name in ("f70.dump", "f70.contacts"):
        assert (one / name).read_bytes() == (two / name).read_bytes(), name
    assert series_data(one / "f70.series") == series_data(two / "f70.series")
    assert f"theta_m = {states[-1][0]:.2f} deg" in said


def test_pieces_read_as_one_ramp(pieced):
    path, _, _, said = pieced
    log = open(path / "log.f0").read()
    steps = angles(path / "log.f0")
    assert len(steps) > 4
    thetas = [t for t, _ in steps]
    assert thetas == pytest.approx([16 + 0.5 * k for k in range(len(thetas))])
    assert steps[-1][1] == "uniform" and [s for _, s in steps[:-1]].count("uniform") == 0
    assert len(re.findall(r"theta_m = ", log)) == 1
    assert log.count("paused after") >= 2, "pieces of 0.2 s pause every few angles"
    assert f"theta_m = {thetas[-1]:.2f} deg" in said, "jobs.txt line"
    assert len(open(path / "f0.wall").read().split()) == log.count("paused after") + 1


def test_outputs_go_forward_in_time(pieced):
    path, _, _, _ = pieced
    times = series_times(path / "f0.series")
    assert all(b >= a for a, b in zip(times, times[1:])), "the killed piece's series line is cut"
    steps = dump_steps(path / "f0.dump")
    assert all(b > a for a, b in zip(steps, steps[1:])), "the killed piece's frame is cut"
    steps = dump_steps(path / "f0.contacts")
    assert all(b > a for a, b in zip(steps, steps[1:]))


@pytest.mark.parametrize("var, value, what", [("tpiece", "-1", "tpiece must be >= 0"),
                                               ("append", "2", "append must be 0 (a new ramp) or 1"),
                                               ("Edem", "-1", "Edem must be a Young modulus > 0 in Pa"),
                                               ("rest", "0", "rest must be a coefficient of restitution in (0, 1]"),
                                               ("tuniform", "2", "tuniform must lie between tchunk (0.001 s) and "
                                                "twin + tfollow (1.3 s), got 2 s")])
def test_bad_piece_variables(tmp_path, var, value, what):
    done = subprocess.run([LMP, "-in", os.path.join(HERE, "in.avalanche"), "-var", "dir", HERE,
                           "-var", var, value, "-log", "log.bad", "-screen", "none", "-nocite"],
                          cwd=tmp_path, capture_output=True, text=True, timeout=60)
    text = open(tmp_path / "log.bad").read()
    assert f"ERROR: {what}" in text, text[-500:]


def test_contact_law_from_the_environment(tmp_path):
    # AVALANCHE_EDEM / AVALANCHE_REST reach the deposit and the ramp, which
    # sets the law again after reading the deposit; the time step follows the
    # modulus as E^(-1/2) (5 us at 1e7 Pa, 2.5 us at 4e7 Pa; the log prints
    # LAMMPS's own dt, the step in force)
    run_ensemble(tmp_path, AVALANCHE_EDEM="4e7", AVALANCHE_REST="0.5")
    text = open(tmp_path / "H3" / "s7" / "log.f0").read()
    assert "contact law Edem 4e7 Pa, restitution 0.5, time step 2.5e-06 s" in text
    assert "theta_m = " in text


def uniform_streak_start(series, hold, eps1=0.3, eps2=0.9, fspread=0.5):
    """Time from the tilt to the first of `hold` consecutive samples with
    sigma_1 < eps1, sigma_2 < eps2 and more than fspread of the grains mobile
    (the series of a t_con run: one angle, a sample per ms after the lines
    printed at the tilt's set-up), measured as in.avalanche does from the
    tilt to the start of the first sample's ms; None if none."""
    rows = [list(map(float, line.split())) for line in series_data(series)]
    t0 = rows[0][0]
    rows = [r for r in rows if r[0] > t0 + 1e-9]
    run = 0
    for k, r in enumerate(rows):
        run = run + 1 if (r[3] < eps1 and r[4] < eps2 and r[7] > fspread) else 0
        if run == hold:
            return rows[k - hold + 1][0] - t0 - 1e-3
    return None


def test_tcon_run_with_a_longer_uniform_hold(tmp_path, whole):
    # run_ensemble.sh tcon0 from the ramp's last static state, with the
    # default hold (10 ms) and with AVALANCHE_TUNIFORM=0.05: the held run
    # has its own log, says its hold, and its t_con is the start of the
    # first 50-sample streak of its series (counted here), never earlier
    # than the default's; both runs are the same computation up to the
    # default's end
    path = tmp_path / "H3" / "s7"
    os.makedirs(path)
    for name in ("deposit.restart", "log.deposit", "log.f0", "f0.static.restart"):
        (path / name).write_bytes((whole / name).read_bytes())
    theta_m = float(re.search(r"theta_m = ([0-9.]+)", open(whole / "log.f0").read()).group(1))
    theta = f"{theta_m + 1:.1f}"
    for hold in ("", "0.05"):
        environ = dict(os.environ, AVALANCHE_OUT=str(tmp_path), AVALANCHE_NP="1", AVALANCHE_FREE="0",
                       AVALANCHE_LAYER="20", AVALANCHE_TCON_STEPS="1", AVALANCHE_TUNIFORM=hold)
        done = subprocess.run(["bash", ENSEMBLE, build_dir(), "3", "7", "tcon0"], env=environ,
                              capture_output=True, text=True, timeout=600)
        assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]
    default, held = path / f"log.tcon_f0_{theta}", path / f"log.tcon_f0_{theta}_u0.05"
    t_default, t_held = (float(re.search(r"theta_m = [0-9.]+ deg  t_con = ([0-9.]+) s", open(log).read()).group(1))
                         for log in (default, held))
    assert "uniform after 0.01 s of sigma_1 < 0.3" in open(default).read()
    assert "uniform after 0.05 s of sigma_1 < 0.3" in open(held).read()
    assert t_held >= t_default
    assert uniform_streak_start(path / f"tcon_f0_{theta}_u0.05.series", 50) == pytest.approx(t_held, abs=2e-4)
    assert uniform_streak_start(path / f"tcon_f0_{theta}.series", 10) == pytest.approx(t_default, abs=2e-4)
    a = series_data(path / f"tcon_f0_{theta}.series")
    assert series_data(path / f"tcon_f0_{theta}_u0.05.series")[:len(a)] == a
