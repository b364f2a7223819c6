"""examples/sound's frictionless packings (study.py run --mu 0) kept apart
from the frictional ones by sound_collect: the samples are told apart by
job.json's mu (none: the paper's 0.5), measured on the frictionless network
(network_moduli model normal), given their own rows and Fig. 4(c), and the
frictional tables stay as they are."""
import json
import os

import numpy as np
import pytest

from acoustic_tools import sound_collect, sound_study, study


def write_sample(out, p, H, seed, mu=None, h=None):
    """a finished sample directory of out: job.json as study.py run writes it
    (mu None: a job.json of before --mu, without mu), a result.json and a
    pulse_A.dat whose peak arrives at t = 4 h"""
    text = "0.5" if mu is None else mu
    directory = out / sound_study.sample_name(p, H, seed, mu=text)
    settings = sound_study.sample_settings(p, H, seed, 24, mu=text)
    if mu is None:
        del settings["mu"]
    study.write_job(str(directory), settings)
    h = float(h or H)
    study.write_result(str(directory), {"W": 24, "D": 0, "h": h, "p": float(p), "p_target": float(p), "seed": seed,
                                        "at_rest": True})
    t = np.linspace(0.0, 12.0 * h, 400)
    f = np.exp(-((t - 4.0 * h) / 3.0) ** 2) / h
    rows = "".join(f"{k + 1} {a:.10g} {b:.10g}\n" for k, (a, b) in enumerate(zip(t, f)))
    (directory / "pulse_A.dat").write_text(f"# pulse\n# TimeStep Number-of-rows\n# Row t F\n0 {len(t)}\n{rows}")
    return directory


@pytest.fixture
def out(tmp_path, monkeypatch):
    """two frictional seeds (one job.json without mu) and three frictionless
    packings at 1e-4 (H 8 and 25 of seed 1, H 25 of seed 2); sample_results
    reads the height and the peak of pulse_A.dat and notes the network model
    it was asked for (the contact network itself is network_moduli's test)"""
    for seed, mu in ((1, None), (2, "0.5")):
        for H in (8, 25):
            write_sample(tmp_path, "1e-4", H, seed, mu, h=H - 0.3 * seed)
    write_sample(tmp_path, "1e-4", 8, 1, "0", h=7.6)
    write_sample(tmp_path, "1e-4", 25, 1, "0", h=24.2)
    write_sample(tmp_path, "1e-4", 25, 2, "0", h=24.4)

    def fake_results(path, result, model="full", mu=0.5):
        h = float(result["h"])
        t10, t_peak, t_zero = 4.0 * h - 3.0, 4.0 * h, 4.0 * h + 3.0
        z_star = 4.1 if model == "normal" else 3.5
        return {"h": h, "p": float(result["p"]), "W": 24.0, "at_rest": True, "model": model, "z_star": z_star,
                "phi2": 0.82, "t10_A": t10, "t_peak_A": t_peak, "t_zero_A": t_zero, "amplitude_A": 1.0 / h,
                "width_A": t_zero - t10, "C11": 0.02, "C11_half": 0.02, "C22": 0.016, "C22_half": 0.016,
                "C12": 0.01, "C12_from_eps11": 0.01, "strain": 1e-5, "C33": 0.0 if model == "normal" else 0.005,
                "C33_half": 0.0 if model == "normal" else 0.005,
                "C22_network": 0.017, "C33_network": 0.0 if model == "normal" else 0.006}

    monkeypatch.setattr(sound_collect, "sample_results", fake_results)
    return tmp_path


def test_sample_name_and_job_record_mu():
    assert sound_study.sample_name("1e-4", 25, 1) == "p1e-4_H25_s1"
    assert sound_study.sample_name("1e-4", 25, 1, mu="0") == "p1e-4_H25_s1_mu0"
    assert sound_study.sample_name("1e-4", 25, 1, "10", "0", "0.1") == "p1e-4_H25_s1_m10_v0_mu0.1"
    assert sound_study.sample_settings("1e-4", 25, 1, mu="0")["mu"] == 0
    assert sound_study.sample_settings("1e-4", 25, 1)["mu"] == 0.5
    # the deck gets -var mu only for another mu than in.packing's 0.5
    frictional = sound_study.sample_command("lmp", ".", "d", sound_study.sample_settings("1e-4", 8, 1), {})
    frictionless = sound_study.sample_command("lmp", ".", "d", sound_study.sample_settings("1e-4", 8, 1, mu="0"),
                                              {"mu": "0"})
    assert "mu" not in frictional
    assert frictionless[frictionless.index("mu") + 1] == "0"


def test_samples_are_told_apart_by_mu(out):
    frictional = sound_collect.samples(str(out))
    frictionless = sound_collect.samples(str(out), mu=sound_collect.FRICTIONLESS)
    assert sorted(frictional) == [(1e-4, 8, 1), (1e-4, 8, 2), (1e-4, 25, 1), (1e-4, 25, 2)]
    assert sorted(frictionless) == [(1e-4, 8, 1), (1e-4, 25, 1), (1e-4, 25, 2)]
    assert all(directory.endswith("_mu0") for directory, _ in frictionless.values())
    assert not any("_mu" in directory for directory, _ in frictional.values())
    # each set on its own network
    _, per_sample, _, _ = sound_collect.usable_samples(str(out))
    assert {r["model"] for r in per_sample.values()} == {"full"}
    _, per_sample, _, _ = sound_collect.usable_samples(str(out), sound_collect.FRICTIONLESS)
    assert {r["model"] for r in per_sample.values()} == {"normal"}


def test_collect_keeps_the_frictionless_apart(out, tmp_path_factory):
    sound_collect.collect(str(out))
    results = json.loads((out / "results.json").read_text())
    text = (out / "tables.md").read_text()
    # the frictional part: the frictional samples only, as without the frictionless ones
    assert sorted(results["samples"]) == ["p0.0001_H25_s1", "p0.0001_H25_s2", "p0.0001_H8_s1", "p0.0001_H8_s2"]
    assert results["pressures"]["0.0001"]["samples"] == 2 and results["pressures"]["0.0001"]["z_star"][0] == 3.5
    alone = tmp_path_factory.mktemp("frictional")
    for name in os.listdir(out):
        if name.startswith("p") and not name.endswith("_mu0"):
            os.symlink(out / name, alone / name)
    sound_collect.collect(str(alone))
    frictional_text = (alone / "tables.md").read_text()
    assert text.startswith(frictional_text.rstrip("\n"))
    assert "frictionless" not in json.loads((alone / "results.json").read_text())
    assert "ACOUSTIC, frictionless" not in frictional_text and "## Frictionless" not in frictional_text
    # the frictionless part: its samples, one H 8 / 25 pair for c_tof, its own rows
    frictionless = results["frictionless"]
    assert sorted(frictionless["samples"]) == ["p0.0001_H25_s1", "p0.0001_H25_s2", "p0.0001_H8_s1"]
    entry = frictionless["pressures"]["0.0001"]
    assert entry["samples"] == 1 and entry["tall_samples"] == 2 and entry["z_star"][0] == 4.1
    assert entry["c_tof_t10"][0] == pytest.approx((24.2 - 7.6) / (4.0 * (24.2 - 7.6)))
    assert entry["moduli_samples"] == "2 / 0" and "C33" not in entry     # frictionless walls: no shear
    section = text[text.index("## Frictionless packings"):]
    assert "| 0.0001 | ACOUSTIC, frictionless | 2 |" in section
    assert "| 0.0001 | ACOUSTIC, frictionless network |" in section
    assert "ACOUSTIC, frictionless" not in text[:text.index("## Frictionless packings")]


def test_fig4c_of_the_frictionless_packings(out, tmp_path):
    figures = tmp_path / "figures"
    figures.mkdir()
    drawn = sound_collect.frictionless_figures(sound_collect.usable_samples(str(out), sound_collect.FRICTIONLESS),
                                               str(figures))
    assert drawn == 2
    assert (figures / "fig4c_signal_frictionless_p1e-4.png").stat().st_size > 1000


def test_fig4d_of_3d_frictionless_packings(out, tmp_path):
    """3D packings (D > 0) are paper 003's Fig. 4(d), in a file of their own"""
    found, per_sample, off_target, not_at_rest = sound_collect.usable_samples(str(out), sound_collect.FRICTIONLESS)
    per_sample = {key: dict(r, D=8.0) for key, r in per_sample.items()}
    drawn = sound_collect.frictionless_figures((found, per_sample, off_target, not_at_rest), str(tmp_path))
    assert drawn == 2
    assert (tmp_path / "fig4d_signal_frictionless_3d_p1e-4.png").stat().st_size > 1000
    assert not (tmp_path / "fig4c_signal_frictionless_p1e-4.png").exists()
