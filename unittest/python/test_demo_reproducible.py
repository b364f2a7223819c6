"""The main job twice: `examples/avalanche/run.sh` (the avalanche demo, 2 MPI
ranks, with and without 70 kHz ultrasound) run twice with the same input must
print the same avalanche angles and write byte-for-byte the same dumps, series
and contact files (the default solver factorises on one rank; a MUMPS team of
two ranks would sum in message order and the flow would amplify that)."""
import filecmp
import os
import re
import subprocess

from acoustic_tools.avalanche_study import KAPPA, job_name, packing_settings, ramp_settings

LMP = os.environ.get("ACOUSTIC_LMP", "lmp")
BUILD = os.path.dirname(os.path.dirname(os.path.abspath(LMP)))
DEMO = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples", "avalanche",
                    "run.sh")
# the two ramps' job directories, named as the demo names them (at the
# calibrated coupling: periodic80_H6_s4871_f0_k0.17, ..._f70_k0.17)
RAMPS = [ramp_settings(packing_settings(6, 4871, free=0, layer=80), f) for f in (0, 70e3)]
OUTPUTS = [f"{job_name(s)}/{s['tag']}.{kind}" for s in RAMPS for kind in ("dump", "contacts", "series")]


def run_demo(out):
    done = subprocess.run(["bash", DEMO, BUILD, "--out", str(out)], capture_output=True, text=True, timeout=1200)
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]
    angles = re.findall(r"^result .*theta_m = ([0-9.]+) deg", done.stdout, re.M)
    return angles


def test_demo_twice_gives_the_same_run(tmp_path):
    first = run_demo(tmp_path / "first")
    second = run_demo(tmp_path / "second")
    assert len(first) == 2, "the demo prints theta_m for 0 and 70 kHz"
    assert all(s["kappa"] == KAPPA for s in RAMPS) and OUTPUTS[-1].startswith("periodic80_H6_s4871_f70_k0.17/")
    assert first == second
    for name in OUTPUTS:
        a, b = tmp_path / "first" / name, tmp_path / "second" / name
        assert a.stat().st_size > 0, name
        assert filecmp.cmp(a, b, shallow=False), f"{name} differs between the two runs"
