"""A tilt ramp of examples/avalanche run as pieces (study.py job with
--piece): every piece ends after a whole angle, the next one goes on
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
import json
import os
import re
import shutil
import subprocess
import sys

import pytest

from acoustic_tools.lammps_log import wall_time

LMP = os.environ.get("ACOUSTIC_LMP", "lmp")
HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples", "avalanche")
STUDY = os.path.join(HERE, "study.py")
# kappa_scale 0.3, not the study's calibrated 0.17: the angles below (a layer
# that creeps from 14 deg and flows at the piece boundaries) were chosen at
# that coupling, and what is tested, the pieces, does not depend on it
KAPPA = "0.3"
RAMP = {"0": "periodic20_H3_s7_f0", "70e3": "periodic20_H3_s7_f70"}      # the job directories (at 0.3)
DEPOSIT = "periodic20_H3_s7_deposit"
ANGLE = re.compile(r"^angle +([0-9.]+) deg: (\w+)")


def build_dir():
    return os.path.dirname(os.path.dirname(os.path.abspath(LMP)))


def run_job(out, freq="0", theta0="16", ranks="1", *options):
    """One ramp of a small periodic layer (3 d thick, 20 d long)."""
    done = subprocess.run([sys.executable, STUDY, "job", "3", "7", freq, "--build", build_dir(), "--out", str(out),
                           "--np", ranks, "--periodic", "--layer", "20", "--theta0", theta0, "--kappa", KAPPA,
                           *options],
                          capture_output=True, text=True, timeout=900)
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]
    return done.stdout


def share_deposit(whole, out):
    """The deposit of the packing made once (the first job of a packing makes it)."""
    shutil.copytree(whole.parent / DEPOSIT, out / DEPOSIT)


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
    run_job(out, "0", "16", "1", "--piece", "0")
    return out / RAMP["0"]


@pytest.fixture(scope="module")
def pieced(tmp_path_factory, whole):
    out = tmp_path_factory.mktemp("pieced")
    share_deposit(whole, out)
    said = run_job(out, "0", "16", "1", "--piece", "0.2", "--max-pieces", "1")
    path = out / RAMP["0"]
    assert "paused after 1 piece" in said
    assert not (path / "result.json").exists(), "no result before the ramp ends"
    first = angle_lines(path / "log.f0")
    # a killed piece: output written past the last whole angle
    theta, tres, step, last, following, carry = open(path / "f0.resume").read().split()
    assert carry in ("f0.last0.in", "f0.last1.in")
    assert float(following) == float(theta) + 0.5, "the next angle, one dtheta on"
    with open(path / "f0.series", "a") as f:
        f.write(f"{float(tres) + 0.0005:.4f} 99 0 0 0 0 0 0 0 0\n")
    with open(path / "f0.dump", "a") as f:
        f.write(f"ITEM: TIMESTEP\n{int(step) + 100}\nITEM: NUMBER OF ATOMS\n0\n")
    with open(path / "log.f0", "a") as f:
        f.write("(killed here)\n")
    # pieces.json: a piece that began 7 s before it wrote its last whole angle
    # and never ended (its LAMMPS total is lost with it)
    pieces = json.load(open(path / "pieces.json"))
    assert len(pieces) == 1 and "end" in pieces[0]
    pieces.append({"start": os.path.getmtime(path / "f0.resume") - 7.0})
    json.dump(pieces, open(path / "pieces.json", "w"))
    said = run_job(out, "0", "16", "1", "--piece", "0.2")
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
        share_deposit(whole, tmp_path / sub)
    run_job(tmp_path / "one", "70e3", "12", "1", "--piece", "2.5", "--max-pieces", "1")
    run_job(tmp_path / "two", "70e3", "12", "1", "--piece", "0.2", "--max-pieces", "2")
    one, two = tmp_path / "one" / RAMP["70e3"], tmp_path / "two" / RAMP["70e3"]
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
        share_deposit(whole, tmp_path / sub)
    # from 14 deg the layer creeps after the pre-ramp and flows from about 17.5
    # deg; a start at 17 deg flowed uniformly at once on one machine (the path of
    # a 70 kHz ramp changes with the BLAS kernels), leaving no boundary to test
    run_job(tmp_path / "one", "70e3", "14", "2", "--tfollow", "0", "--piece", "0")
    said = run_job(tmp_path / "two", "70e3", "14", "2", "--tfollow", "0", "--piece", "0.05")
    one, two = tmp_path / "one" / RAMP["70e3"], tmp_path / "two" / RAMP["70e3"]
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
    assert f"theta_m = {states[-1][0]} deg" in said
    assert json.load(open(one / "result.json"))["angles"] == json.load(open(two / "result.json"))["angles"]


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
    assert f"theta_m = {thetas[-1]} deg" in said, "the run's line"
    # result.json: every angle of every piece, as the log's angle lines say
    result = json.load(open(path / "result.json"))
    assert [(a["theta"], a["state"]) for a in result["angles"]] == steps
    assert result["theta_m"] == thetas[-1] and result["settled"] in ("at rest", "NOT at rest after tsettle")
    assert json.load(open(path / "job.json"))["piece"] == "0.2"
    # the LAMMPS totals of the pieces that ended, and the killed one's 7 s
    assert result["wall_time"] == round(wall_time(str(path / "log.f0")) + 7.0)
    assert json.load(open(path / "pieces.json"))[1]["kept"] == pytest.approx(7.0)


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
                                                "twin + tfollow (1.3 s), got 2 s"),
                                               ("setup", "2", "setup must be 1 (a set-up before the first angle) "
                                                "or 0"),
                                               ("setup", "0", "setup 0 needs -var pre 0")])
def test_bad_piece_variables(tmp_path, var, value, what):
    done = subprocess.run([LMP, "-in", os.path.join(HERE, "in.avalanche"), "-var", "dir", HERE,
                           "-var", var, value, "-log", "log.bad", "-screen", "none", "-nocite"],
                          cwd=tmp_path, capture_output=True, text=True, timeout=60)
    text = open(tmp_path / "log.bad").read()
    assert f"ERROR: {what}" in text, text[-500:]


def test_contact_law_from_the_options(tmp_path):
    # --edem / --rest reach the deposit and the ramp, which
    # sets the law again after reading the deposit; the time step follows the
    # modulus as E^(-1/2) (5 us at 1e7 Pa, 2.5 us at 4e7 Pa; the log prints
    # LAMMPS's own dt, the step in force)
    run_job(tmp_path, "0", "16", "1", "--edem", "4e7", "--rest", "0.5")
    text = open(tmp_path / "periodic20_E4e7_e0.5_H3_s7_f0" / "log.f0").read()
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
    # study.py job --tcon from the ramp's last static state, with the
    # default hold (10 ms) and with --tuniform 0.05: the held run
    # has its own log, says its hold, and its t_con is the start of the
    # first 50-sample streak of its series (counted here), never earlier
    # than the default's; both runs are the same computation up to the
    # default's end
    shutil.copytree(whole, tmp_path / RAMP["0"])
    theta_m = json.load(open(whole / "result.json"))["theta_m"]
    theta = f"{theta_m + 1:.1f}"
    for hold in ([], ["--tuniform", "0.05"]):
        run_job(tmp_path, "0", "16", "1", "--tcon", "--tcon-steps", "1", *hold)
    base = tmp_path / f"periodic20_H3_s7_tcon_f0_{theta}"
    default, held = base / f"log.tcon_f0_{theta}", tmp_path / f"{base.name}_u0.05" / f"log.tcon_f0_{theta}_u0.05"
    t_default, t_held = (json.load(open(log.parent / "result.json"))["t_con"] for log in (default, held))
    assert json.load(open(held.parent / "job.json"))["tuniform"] == 0.05
    assert "uniform after 0.01 s of sigma_1 < 0.3" in open(default).read()
    assert "uniform after 0.05 s of sigma_1 < 0.3" in open(held).read()
    assert t_held >= t_default
    assert uniform_streak_start(held.parent / f"tcon_f0_{theta}_u0.05.series", 50) == pytest.approx(t_held, abs=2e-4)
    assert uniform_streak_start(base / f"tcon_f0_{theta}.series", 10) == pytest.approx(t_default, abs=2e-4)
    a = series_data(base / f"tcon_f0_{theta}.series")
    assert series_data(held.parent / f"tcon_f0_{theta}_u0.05.series")[:len(a)] == a


def test_tcon_run_from_a_moving_state_is_the_ramps_next_angle_bit_for_bit(tmp_path, whole, monkeypatch):
    """A t_con run from the ramp's last static state (written at the end of
    its last stable, stopped or local angle) at the ramp's next angle makes
    no set-up of its own before the angle (setup 0), as the ramp made none
    there: it is that angle of the ramp again, sample for sample -- the
    fields set holds the ramp's flow at theta_m longer.  At 70 kHz on 2
    ranks with angles of 0.1 s the layer may still move where that state
    is written; whether it does depends on the trajectory, which changes
    from machine to machine, so three ramps (from 12, 14 and 15 deg) are
    run, and in at least one of them the same run with the set-up a new run
    made before (setup 1, which rescales the tangential history of the
    sliding contacts) is another flow: the control that the test tells the
    two apart."""
    from acoustic_tools import avalanche_study as study
    made = study.tcon_settings
    told_apart = []
    for theta0 in ("12", "14", "15"):
        top = tmp_path / theta0
        share_deposit(whole, top)
        run_job(top, "70e3", theta0, "2", "--tfollow", "0", "--piece", "0")
        ramp_dir = top / RAMP["70e3"]
        ramp = json.load(open(ramp_dir / "result.json"))
        angles_of = ramp["angles"]
        last = max(k for k, a in enumerate(angles_of) if a["state"] in ("stable", "stopped", "local"))
        assert last + 1 < len(angles_of), "an angle after the last static state"
        theta = angles_of[last + 1]["theta"]
        run_job(top, "70e3", theta0, "2", "--tfollow", "0", "--tcon", "--tcon-steps", f"{theta - ramp['theta_m']:g}")
        tag = f"tcon_f70_{theta:.1f}"
        d = top / f"periodic20_H3_s7_{tag}"
        assert json.load(open(d / "result.json"))["angles"] == [angles_of[last + 1]]

        def at(path):
            return [line for line in series_data(path) if float(line.split()[1]) == theta]

        assert len(at(ramp_dir / "f70.series")) > 50
        assert at(d / f"{tag}.series") == at(ramp_dir / "f70.series"), f"from {theta0} deg"
        assert "no set-up before the first angle (setup 0)" in open(d / f"log.{tag}").read()
        # the control: the same t_con run (Runner.tcon, the ramp's own
        # job.json) with setup 1, from a copy of the ramp
        control = top / "control"
        shutil.copytree(ramp_dir, control / RAMP["70e3"])
        with monkeypatch.context() as m:
            m.setattr(study, "tcon_settings", lambda *args, **kw: dict(made(*args, **kw), setup=1))
            runner = study.Runner(build_dir(), str(control), HERE, np=2, say=lambda text: None)
            runner.tcon(json.load(open(ramp_dir / "job.json")), steps=(theta - ramp["theta_m"],))
        assert json.load(open(control / d.name / "job.json"))["setup"] == 1
        told_apart.append(at(control / d.name / f"{tag}.series") != at(ramp_dir / "f70.series"))
    assert any(told_apart), "in one ramp at least the set-up makes another flow: a state with sliding contacts"
