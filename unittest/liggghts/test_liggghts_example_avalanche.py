"""LIGGGHTS example examples/liggghts_avalanche (paper 000's inclined plane):
its run.sh, cut short, runs the deposit and both tilt ramps (0 Hz and
70 kHz from the vibrating STL base mesh) on 2 MPI ranks through the decks
and prints both result lines.

A few grains (in.deposit -var N 40, short fall and relaxation), two angles
(2 and 2.5 deg) watched 3 ms each after a short pre-ramp: the point is
that every part of the decks runs (insertion, the STL mesh and its wall,
restart, tilted gravity, fix acoustic/mindlin with source mesh, the angle
loop and the result line), not the angles themselves.

Needs ACOUSTIC_LIGGGHTS (lmp_acoustic) and mpirun."""
import os
import re
import subprocess

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLE = os.path.join(HERE, "..", "..", "examples", "liggghts_avalanche")


def test_run_sh_prints_both_avalanche_angles(tmp_path):
    exe = os.environ.get("ACOUSTIC_LIGGGHTS")
    if not exe:
        pytest.fail("ACOUSTIC_LIGGGHTS is not set: set it to the LIGGGHTS executable lmp_acoustic")
    if not (os.path.isfile(exe) and os.access(exe, os.X_OK)):
        pytest.fail("ACOUSTIC_LIGGGHTS=%s is not an executable file" % exe)
    env = dict(os.environ)
    env.update(OUT=str(tmp_path), NP="2",
               DEPOSIT_VARS="-var N 40 -var tfall 0.02 -var tcalm 0.005 -var trest 0.005")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    env.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")
    env.setdefault("OMPI_MCA_mpi_yield_when_idle", "1")
    cmd = [os.path.join(EXAMPLE, "run.sh"), os.path.abspath(exe),
           "-var", "theta0", "2", "-var", "thetamax", "2.5", "-var", "tpre", "0.0005",
           "-var", "tsettle", "0.002", "-var", "twin", "0.003", "-var", "tfollow", "0",
           "-var", "thold", "0.002", "-var", "tflow", "0.002"]
    proc = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, errors="replace", timeout=600)
    out = proc.stdout
    print(out)
    assert proc.returncode == 0, out[-3000:]
    assert "ERROR" not in out
    assert re.search(r"deposit: \d+ grains on 50 base grains", out), out
    # both ramps ran with the mesh source and tested their angles
    for freq in ("0", "70000"):
        assert re.search(r"avalanche f\d+: \d+ grains, 50 base grains, freq %s Hz.*source mesh"
                         % freq, out), out
    angles = re.findall(r"angle (\d+\.\d) deg: (stable|stopped|moving|avalanche) after (\d+) ms", out)
    assert len(angles) >= 2, out
    assert all(a[0] in ("2.0", "2.5") for a in angles), angles
    results = re.findall(r"^result: f = (\d+) Hz theta_m = (\S+) deg$", out, re.M)
    assert [r[0] for r in results] == ["0", "70000"], out
    for _, theta in results:
        assert theta in ("none", "2.0", "2.5"), results
    assert re.search(r"theta_m without ultrasound: \S+ deg; with 70 kHz: \S+ deg", out), out
    # the 70 kHz run reduced friction (mean factor below 1), the 0 Hz run did not
    f0 = [float(m) for m in re.findall(r"mean mu\*/mu (\d\.\d{3})", out.split("avalanche f70")[0])]
    f70 = [float(m) for m in re.findall(r"mean mu\*/mu (\d\.\d{3})", out.split("avalanche f70")[1])]
    assert f0 and all(s == 1.0 for s in f0), f0
    assert f70 and all(s < 1.0 for s in f70), f70
