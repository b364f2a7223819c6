"""examples/sound end to end on small systems, through its entry point
examples/sound/study.py: `run` runs the decks in LAMMPS (a small confined
packing and a short 1D chain, two jobs at a time), each job's job.json and
result.json are checked, and `collect` turns them into results.json and
tables.md.  The 1D chain must show paper 003's exponents (gamma = 2/3 for
condition A, 1 for B); a small confined packing must reach its pressure at
rest and carry a pulse at about paper 003's speed; a small frictionless
packing (run --mu 0) is measured on the frictionless network (model
normal) and collected apart from the frictional one."""
import json
import os
import subprocess
import sys

import numpy as np
import pytest

from acoustic_tools import lammps_output, network_moduli, sound, sound_chain, study

LMP = os.environ.get("ACOUSTIC_LMP", "lmp")
HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples", "sound")


def study_py(cwd, *arguments):
    """examples/sound/study.py with these arguments; its stdout"""
    done = subprocess.run([sys.executable, os.path.join(HERE, "study.py")] + list(arguments), cwd=cwd,
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stdout + done.stderr
    return done.stdout


@pytest.fixture(scope="module")
def jobs(tmp_path_factory):
    """study.py run of one small packing (W = H = 8, p = 1e-4, thermo every
    10 steps of the compression) and of the chain N = 32, 64, 128; then the
    same packing frictionless (--mu 0) beside it"""
    out = tmp_path_factory.mktemp("sound")
    printed = study_py(out, "run", "--lmp", LMP, "--out", str(out), "--jobs", "2", "--pressures", "1e-4",
                       "--heights", "8", "--seeds", "1", "--width", "8", "--var", "thermo_every", "10",
                       "--chain", "--chain-sizes", "32", "64", "128", "--chain-poly", "0.1", "--chain-poly-sizes", "16",
                       "32", "--chain-realizations", "2", "--lattice-series", "1e-4", "--lattice-series-rows", "4", "8",
                       "12")
    printed += study_py(out, "run", "--lmp", LMP, "--out", str(out), "--jobs", "1", "--pressures", "1e-4",
                        "--heights", "8", "--seeds", "1", "--width", "8", "--mu", "0")
    return out, printed


def test_run_writes_job_and_result(jobs):
    out, printed = jobs
    sample = out / "p1e-4_H8_s1"
    assert "p=1e-4 H=8 seed=1: moduli: sigma1/sigma2" in printed
    settings = study.read_job(str(sample))
    assert settings == {"kind": "sample", "deck": "in.sound", "p": 1e-4, "H": 8, "seed": 1, "W": 8, "D": 0,
                        "piston_mass": 1, "piston_speed": 0.001, "mu": 0.5, "variables": {"thermo_every": "10"}}
    result = study.read_result(str(sample))
    assert result["at_rest"] is True and result["p_target"] == 1e-4 and result["W"] == 8
    assert result["wall_seconds"] >= 0
    for key in ("h", "p", "p_peak", "N", "max_acceleration", "packing_steps", "C11", "C33_half"):
        assert isinstance(result[key], (int, float)), key
    # the old key-value files are gone: result.json is the sample's one result
    for name in ("summary.txt", "moduli.txt", "checks.txt"):
        assert not (sample / name).exists(), name
    # a second run finds everything done and runs nothing
    assert study_py(out, "run", "--lmp", LMP, "--out", str(out), "--pressures", "1e-4", "--heights", "8",
                    "--seeds", "1", "--width", "8", "--chain", "--chain-sizes", "32", "64", "128") == ""
    assert study_py(out, "run", "--lmp", LMP, "--out", str(out), "--no-samples", "--chain-poly", "0.1",
                    "--chain-poly-sizes", "16", "32", "--chain-realizations", "2") == ""


def test_chain_is_appendix_c(jobs):
    """in.chain's chain of identical balls with identical springs at the
    walls is Appendix C's: its signals are Eqs. C4-C6 (in the compute's
    normalisation: A u'_1 = K / m, B u_1 = 1), and its amplitude exponents
    approach 2/3 (A) and 1 (B) as the closed form's do"""
    out, _ = jobs
    chain = out / "chain"
    result = study.read_result(str(chain))
    assert result["N"] == [32, 64, 128] and result["free_dofs"] == [2 * n for n in (32, 64, 128)]
    assert result["wall_spring_over_K"] == pytest.approx(1.0, rel=1e-12)
    f = result["p"]
    stiffness, mass, spacing = 0.5 * (3 * f) ** (1 / 3), np.pi / 6, 1.0 - (3 * f) ** (2 / 3)
    speed = spacing * np.sqrt(stiffness / mass)
    for condition, scale, gamma in (("A", stiffness / mass / speed, 2 / 3), ("B", 1.0 / spacing, 1.0)):
        amplitudes = []
        for n in result["N"]:
            t, signal = sound.read_pulse(str(chain / f"chain_{condition}_{n}.dat"))
            closed = scale * sound_chain.chain_signal(n, t, condition, stiffness, mass, spacing)
            assert np.max(np.abs(signal - closed)) < 1e-8 * np.max(np.abs(closed)), (condition, n)
            amplitudes.append(sound.coherent_peak(t, signal)["amplitude"])
        slopes = -sound.effective_exponents(result["N"], amplitudes)[1]
        assert slopes[0] < slopes[1] < gamma + 0.01, condition


def test_polydisperse_chain_and_lattice(jobs):
    """the polydisperse chains are the Hertz chains of their grains; the
    lattice is its chain of rows, per ball (sound_chain)"""
    out, _ = jobs
    chain = out / "chain_poly0.1"
    result = study.read_result(str(chain))
    assert result["poly"] == 0.1 and result["realizations"] == 2 and result["N"] == [16, 32]
    for n in (16, 32):
        for r in (1, 2):
            _, diameters, _ = sound_chain.read_chain_grains(str(chain / f"chain_{n}_{r}.grains"))
            assert len(diameters) == n and 0.9 <= diameters.min() and diameters.max() <= 1.1
            masses, springs = sound_chain.hertz_chain(diameters, result["p"])
            t, signal = sound.read_pulse(str(chain / f"chain_A_{n}_{r}.dat"))
            model = sound_chain.linear_chain_signal(masses, springs, t, "A")
            assert np.max(np.abs(signal - model)) < 1e-8 * np.max(np.abs(signal))
    lattice = out / "lattice_p1e-4_M4"
    result = study.read_result(str(lattice))
    assert result["rows"] == [4, 8, 12] and result["M"] == 4
    for model, eta in (("normal", 0.0), ("full", 1.0)):
        t, signal = sound.read_pulse(str(lattice / f"lattice_{model}_B_8.dat"))
        masses, springs = sound_chain.lattice_row_chain(8, 1e-4, eta, spacing=result["a"])
        rows = 4 * sound_chain.linear_chain_signal(masses, springs, t, "B")
        assert np.max(np.abs(signal - rows)) < 1e-5 * np.max(np.abs(signal)), model


def test_collect_reads_the_jobs(jobs):
    out, _ = jobs
    printed = study_py(out, "collect", "--out", str(out))
    assert (out / "tables.md").read_text() == printed
    results = json.loads((out / "results.json").read_text())
    sample = results["samples"]["p0.0001_H8_s1"]
    result = study.read_result(str(out / "p1e-4_H8_s1"))
    assert sample["C22"] == result["C22"] and sample["h"] == result["h"]
    assert sample["sigma_ratio"] == result["checks"]["sigma_ratio"] and sample["at_rest"] is True
    assert results["chain"]["A"]["N"] == [32, 64, 128] and len(results["chain"]["A"]["gamma_eff"]) == 2
    assert results["pressures"]["0.0001"]["samples"] == 0     # no H = 25 partner: no time of flight
    assert "| 0.0001 | ACOUSTIC |" in printed and "chain A: N [32, 64, 128]" in printed
    assert results["chain"]["model_deviation"] < 1e-8 and results["chain_poly"]["0.1"]["realizations"] == 2
    assert "Table III" in printed and "| 1D chain, diameters uniform in 1 ± 0.1 | A |" in printed
    assert results["lattice_series"]["frictionless, p = 0.0001, A"]["N"] == [4, 8, 12]


def thermo_columns(log_text, first):
    """the numeric rows of every thermo table of a log whose header starts
    with `first`, as a dict of columns"""
    rows, names = [], None
    for line in log_text.splitlines():
        words = line.split()
        if words and words[0] == "Step" and len(words) > 1 and words[1] == first:
            names = words
            continue
        if names and len(words) == len(names):
            try:
                rows.append([float(w) for w in words])
                continue
            except ValueError:
                pass
    table = np.array(rows)
    return {name: table[:, k] for k, name in enumerate(names)}


def test_small_packing(jobs):
    out, _ = jobs
    tmp_path = out / "p1e-4_H8_s1"
    log = (tmp_path / "log.lammps").read_text()
    summary = study.read_result(str(tmp_path))
    assert summary["p"] == pytest.approx(1e-4, rel=0.02)
    assert summary["max_acceleration"] < 1e-10
    assert "packing: at rest" in log
    assert "fix             drag" not in log.split("packing: at rest")[0], "no drag while packing"
    # the piston moves continuously under its constant force: between two
    # thermo lines (10 steps) it moves no farther than it could fall freely
    # from its start with the whole force p A on it (energy: v^2 <= 2 p A
    # (h0 - h) / M), i.e. no jumps
    compression = thermo_columns((tmp_path / "compression.log").read_text(), "v_h")
    h, step = compression["v_h"], compression["Step"]
    assert h[0] - h[-1] > 5.0, "the piston came down"
    dt = 0.15 * np.sqrt(np.pi / 6 * 0.512 / (2 * 0.5 * (3 * 10 * 1e-4) ** (1 / 3)))
    area, mass = 8.0 * 1.0, summary["piston_mass"] * np.sum(
        lammps_output.read_dump(str(tmp_path / "grains.dump"))[-1]["mass"])
    fastest = np.sqrt(2 * 1e-4 * area * (h[0] - h.min()) / mass)
    moves = np.abs(np.diff(h)) / np.maximum(np.diff(step), 1)
    assert moves.max() <= fastest * dt * 1.01, "a jump of the piston"
    # the paper's anisotropy of a load-controlled compression: sigma1/sigma2 < 1
    checks = summary["checks"]
    assert checks["sigma_ratio"] < 1.0
    for key in sound.CHECKS:
        assert key in checks, key
    assert "checks: z_star" in log
    # the static network: every contact loaded, the bottom wall among them
    contacts = lammps_output.read_dump(str(tmp_path / "contacts.dump"))[-1]
    assert np.all(contacts[2] > 0.0)
    assert np.any(contacts[1] == 0)
    # the pulse crosses the layer at about c = 0.26 (paper 003 at p = 1e-4)
    t, f = sound.read_pulse(str(tmp_path / "pulse_A.dat"))
    peak = sound.coherent_peak(t, f)
    assert summary["h"] / peak["t_peak"] == pytest.approx(0.26, rel=0.3)
    moduli = summary
    for key in ("C11", "C12", "C22", "C33"):
        assert moduli[key] > 0.0, key
    # the DEM's moduli are those of the linear contact network (C33 a little
    # lower in the DEM: the shear's new wall fix starts without tangential history)
    grains = lammps_output.read_dump(str(tmp_path / "grains.dump"))[-1]
    network = network_moduli.network_moduli(grains, contacts, summary["W"], summary["h"])
    assert moduli["C22"] == pytest.approx(network["C22"], rel=0.1)
    assert moduli["C33"] == pytest.approx(network["C33"], rel=0.25)
    assert "moduli: sigma1/sigma2" in log
    # the tangential forces of pair granular (tangential.dump): the grain-grain
    # contacts of the network, each within the Coulomb condition |F_t| <= mu F_n
    # with the F_n of the network (which leaves out the damping of the grains' residual motion)
    tangential = lammps_output.read_dump(str(tmp_path / "tangential.dump"))[-1]
    pairs = {tuple(sorted((int(i), int(j)))): f for i, j, f in zip(contacts[0], contacts[1], contacts[2]) if j != 0}
    dumped = {tuple(sorted((int(i), int(j)))): (fn, ft) for i, j, fn, ft in zip(*(tangential[k] for k in range(4)))}
    assert set(dumped) == set(pairs)
    for key, (fn, ft) in dumped.items():
        assert fn == pytest.approx(pairs[key], rel=1e-4) and ft <= 0.5 * fn * (1.0 + 1e-9), key
    assert 0.0 <= sound.mobilisation(tangential[2], tangential[3], 0.5)["fraction_at_limit"] < 1.0


def test_frictionless_packing(jobs):
    """run --mu 0: the packing of mu = 0 in its own directory, mu in
    job.json, measured on the frictionless network: model normal in the
    pulse's log line, 2 modes per grain (the frictional one: 3), of which
    the rattlers' and the layer's sliding along the frictionless walls are
    zero; no shear modulus (the walls carry no shear); collected apart"""
    out, printed = jobs
    sample = out / "p1e-4_H8_s1_mu0"
    assert "p=1e-4 H=8 seed=1 mu=0: moduli: sigma1/sigma2" in printed
    settings = study.read_job(str(sample))
    assert settings["mu"] == 0 and settings["H"] == 8 and settings["W"] == 8
    assert study.read_job(str(out / "p1e-4_H8_s1"))["mu"] == 0.5
    log = (sample / "log.lammps").read_text()
    assert "model normal (mu = 0)" in log and "mindlin/acoustic NULL 1.0 0" in log
    result = study.read_result(str(sample))
    assert result["at_rest"] is True and result["p"] == pytest.approx(1e-4, rel=0.02)
    grains = lammps_output.read_dump(str(sample / "grains.dump"))[-1]
    contacts = lammps_output.read_dump(str(sample / "contacts.dump"))[-1]
    omega2 = lammps_output.read_ave_time_vector(str(sample / "modes.dat"))[-1][1][:, 0]
    assert len(omega2) == 2 * result["N"] == 2 * len(grains["id"])
    frictional = study.read_result(str(out / "p1e-4_H8_s1"))
    assert len(lammps_output.read_ave_time_vector(str(out / "p1e-4_H8_s1" / "modes.dat"))[-1][1]) == 3 * frictional["N"]
    rattlers = sound.rattlers(grains["id"], contacts[0], contacts[1])
    assert np.sum(omega2 < 1e-6 * omega2.max()) >= 2 * len(rattlers) + 1
    # the pulse crosses the layer; the DEM's C22 is the frictionless network's
    t, f = sound.read_pulse(str(sample / "pulse_A.dat"))
    assert result["h"] / sound.coherent_peak(t, f)["t_peak"] == pytest.approx(0.26, rel=0.4)
    network = network_moduli.network_moduli(grains, contacts, result["W"], result["h"], model="normal")
    assert result["C22"] == pytest.approx(network["C22"], rel=0.15)
    assert abs(result["C33"]) < 1e-3 * result["C22"] and network["C33"] == 0.0
    # collect: the frictionless sample apart, the frictional one where it was
    study_py(out, "collect", "--out", str(out))
    results = json.loads((out / "results.json").read_text())
    assert list(results["frictionless"]["samples"]) == ["p0.0001_H8_s1"]
    assert results["frictionless"]["samples"]["p0.0001_H8_s1"]["C22_network"] == pytest.approx(network["C22"])
    assert results["samples"]["p0.0001_H8_s1"]["C22"] == frictional["C22"]
    assert "## Frictionless packings" in (out / "tables.md").read_text()
