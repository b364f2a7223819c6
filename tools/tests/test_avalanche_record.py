"""examples/avalanche/record.py (acoustic_tools.avalanche_record) on
synthetic run directories: it keeps only the lines collect.py reads, leaves
unfinished ramps out, keeps jobs recorded earlier, and collect.py reads the
same per-packing numbers from the record as from the full outputs."""
import os
import subprocess
import sys

import pytest

RECORD = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples", "avalanche", "record.py")


DEPOSIT = "deposit: 500 grains on 80 base grains, box 80.0 d long, layer H = 6.10 d (target 6), free ends 1\n"
RAMP = [
    "LAMMPS (4 Feb 2025)\n",
    "  Step Time v_theta\n",
    "  1000 0.005 18\n",
    "avalanche f0: 500 grains, 80 base grains, freq 0 Hz, U0/d 1e-4\n",
    "avalanche f0: pre-ramp to 17.50 deg done at t = 0.300 s, E_k/E_t = 1.00e-09 (at rest)\n",
    "angle 18.00 deg: stable after 0.100 s  max E_k/E_t 1e-09  max mobile fraction 0.000  "
    "sigma1 1 sigma2 1  mean mu*/mu 1.000\n",
    "Loop time of 12.5 on 2 procs for 1000 steps with 580 atoms\n",
    "Total wall time: 0:01:05\n",
    "angle 18.50 deg: uniform after 0.300 s  max E_k/E_t 1e-01  max mobile fraction 0.900  "
    "sigma1 0.1 sigma2 0.5  mean mu*/mu 1.000\n",
    "avalanche f0: freq 0 Hz  theta_m = 18.50 deg  t_con = 0.250 s\n",
    "Total wall time: 0:00:55\n",
]


def packing(top, seed, f70_finished, geometry="ensemble"):
    d = top / geometry / "H6" / f"s{seed}"
    os.makedirs(d)
    (d / "log.deposit").write_text("LAMMPS (4 Feb 2025)\n" + DEPOSIT + "Total wall time: 0:00:30\n")
    (d / "log.f0").write_text("".join(RAMP))
    f70 = RAMP[:6] if not f70_finished else RAMP
    (d / "log.f70").write_text("".join(f70).replace("f0", "f70"))
    (d / "f0.dump").write_text("ITEM: TIMESTEP\n0\n")
    (d / "log.f0.resume").write_text("LAMMPS (4 Feb 2025)\n" + RAMP[-2])
    return d


def test_only_result_lines_of_finished_jobs(record, tmp_path):
    out, rec = tmp_path / "out", tmp_path / "rec"
    packing(out, 1, f70_finished=False)
    (out / "ensemble" / "jobs.txt").write_text("H6 s1 f0: theta_m = 18.50 deg  wall 120 s\n")
    assert record.record(str(out), str(rec)) == 2
    d = rec / "ensemble" / "H6" / "s1"
    assert sorted(os.listdir(d)) == ["log.deposit", "log.f0"], "no dump, no piece's own log, no unfinished ramp"
    dropped = ("LAMMPS", "  ", "Loop time")
    assert (d / "log.f0").read_text() == "".join(line for line in RAMP if not line.startswith(dropped))
    assert (d / "log.deposit").read_text() == DEPOSIT + "Total wall time: 0:00:30\n"
    assert (rec / "ensemble" / "jobs.txt").read_text() == (out / "ensemble" / "jobs.txt").read_text()


def test_record_grows_across_machines(record, tmp_path):
    first, second, rec = tmp_path / "first", tmp_path / "second", tmp_path / "rec"
    packing(first, 1, f70_finished=True)
    (first / "ensemble" / "jobs.txt").write_text("job s1 f0\njob s1 f70\n")
    record.record(str(first), str(rec))
    packing(second, 2, f70_finished=True)
    (second / "ensemble" / "jobs.txt").write_text("job s1 f70\njob s2 f0\n")
    record.record(str(second), str(rec))
    assert sorted(os.listdir(rec / "ensemble" / "H6")) == ["s1", "s2"], "the first machine's packing is kept"
    assert (rec / "ensemble" / "jobs.txt").read_text() == "job s1 f0\njob s1 f70\njob s2 f0\n", \
        "a job line already recorded is not written twice"


def test_collect_reads_the_record_as_the_outputs(record, collect, tmp_path):
    out, rec = tmp_path / "out", tmp_path / "rec"
    packing(out, 1, f70_finished=True)
    packing(out, 2, f70_finished=True)
    record.record(str(out), str(rec))
    full = collect.ensembles(str(out))["free ends, 400 d"][6.0]
    kept = collect.ensembles(str(rec))["free ends, 400 d"][6.0]
    keys = ("seed", "grains", "base", "H_measured", "length", "f0", "f70", "f0_wall", "f70_wall",
            "f0_rest", "f0_onset", "f70_onset")
    assert [{k: p[k] for k in keys} for p in kept] == [{k: p[k] for k in keys} for p in full]
    assert kept[0]["f0"] == (18.5, 0.25) and kept[0]["f0_wall"] == 120 and kept[0]["f70_onset"] == 18.5
    assert kept[0]["f0_rest"] == "at rest"


def test_no_outputs_is_an_error(tmp_path):
    done = subprocess.run([sys.executable, RECORD, str(tmp_path / "missing"), str(tmp_path / "rec")],
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == 1 and "no production outputs" in done.stderr


def test_deposit_under_way_left_out(record, tmp_path):
    # a packing whose deposit is still running: its log has no deposit line yet
    out, rec = tmp_path / "out", tmp_path / "rec"
    d = packing(out, 1, f70_finished=False)
    (d / "log.deposit").write_text("LAMMPS (4 Feb 2025)\n  Step Time\n")
    assert record.record(str(out), str(rec)) == 1
    assert os.listdir(rec / "ensemble" / "H6" / "s1") == ["log.f0"]


def test_layers_of_another_length_recorded(record, collect, tmp_path):
    # run_ensemble.sh with AVALANCHE_LAYER=800 writes out/ensemble_L800: its
    # logs and jobs are recorded as those of the 400 d set
    out, rec = tmp_path / "out", tmp_path / "rec"
    packing(out, 1, f70_finished=True, geometry="ensemble_L800")
    (out / "ensemble_L800" / "jobs.txt").write_text("H6 s1 f0: theta_m = 18.50 deg  layer 800 d\n")
    assert record.record(str(out), str(rec)) == 3
    assert sorted(os.listdir(rec / "ensemble_L800" / "H6" / "s1")) == ["log.deposit", "log.f0", "log.f70"]
    assert (rec / "ensemble_L800" / "jobs.txt").read_text() == (out / "ensemble_L800" / "jobs.txt").read_text()
    assert collect.ensembles(str(rec))["free ends, 800 d"][6.0][0]["f0"] == (18.5, 0.25)


@pytest.mark.parametrize("geometry, label", [("ensemble_E1e8", "free ends, 400 d, E = 1e+08 Pa"),
                                             ("ensemble_e0.05", "free ends, 400 d, restitution 0.05")])
def test_sets_of_another_contact_law_recorded(record, collect, tmp_path, geometry, label):
    # run_ensemble.sh with AVALANCHE_EDEM=1e8 writes out/ensemble_E1e8, with
    # AVALANCHE_REST=0.05 out/ensemble_e0.05
    out, rec = tmp_path / "out", tmp_path / "rec"
    packing(out, 1, f70_finished=True, geometry=geometry)
    assert record.record(str(out), str(rec)) == 3
    assert sorted(os.listdir(rec / geometry / "H6" / "s1")) == ["log.deposit", "log.f0", "log.f70"]
    assert collect.ensembles(str(rec))[label][6.0][0]["f0"] == (18.5, 0.25)


@pytest.mark.parametrize("kset", ["kappa", "kappa_free"])
def test_kappa_studies_recorded(record, collect, tmp_path, kset):
    # run_production.sh's kappa (periodic) and kappa_free (free ends) sets
    # write out/<kset>/k<kappa>; the record keeps them beside their reference
    # set, and collect.py pairs them the same way from the record
    out, rec = tmp_path / "out", tmp_path / "rec"
    reference = collect.KAPPA_SETS[kset][0]
    packing(out, 1, f70_finished=True, geometry=reference)
    packing(out, 1, f70_finished=True, geometry=f"{kset}/k0.1")
    assert record.record(str(out), str(rec)) == 6
    assert sorted(os.listdir(rec / kset / "k0.1" / "H6" / "s1")) == ["log.deposit", "log.f0", "log.f70"]
    assert collect.kappa_study(str(rec), kset) == collect.kappa_study(str(out), kset)
    assert [r[0] for r in collect.kappa_study(str(rec), kset)] == [0.1, 0.3]


def test_switch_on_study_recorded(record, collect, tmp_path):
    # run_production.sh's switch_on set writes out/switch_on/at<angle>: 70 kHz ramps
    # of packings of the free-ends set, switched on 0.5 deg above that angle
    out, rec = tmp_path / "out", tmp_path / "rec"
    packing(out, 1, f70_finished=True)
    late = packing(out, 1, f70_finished=True, geometry="switch_on/at17")
    (late / "log.f70").write_text((late / "log.f70").read_text().replace("angle 18.00", "angle 17.50"))
    assert record.record(str(out), str(rec)) == 6
    assert collect.switch_on_study(str(rec)) == collect.switch_on_study(str(out))
    assert [r[3] for r in collect.switch_on_study(str(rec))] == [17.5, 18.0]
