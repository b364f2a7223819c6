"""study.record_jobs and the sound study's record: what a study's record
keeps of its finished jobs; and study.mpirun, the launcher of its jobs"""
import json
import os
import shutil
import subprocess
import sys

import pytest

from acoustic_tools import sound_study, study


def make_job(out, name, finished=True, log=None):
    directory = out / name
    directory.mkdir(parents=True)
    study.write_job(str(directory), {"name": name})
    if finished:
        study.write_result(str(directory), {"value": 1.5})
    if log is not None:
        (directory / "log.lammps").write_text(log)
    return directory


def test_record_copies_finished_jobs_only(tmp_path):
    out, dest = tmp_path / "out", tmp_path / "record"
    make_job(out, "a")
    make_job(out, "b", finished=False)
    (dest / "old").mkdir(parents=True)          # recorded earlier, absent from out: kept
    assert study.record_jobs(str(out), str(dest)) == 1
    assert sorted(os.listdir(dest)) == ["a", "old"]
    assert json.loads((dest / "a" / study.RESULT).read_text())["value"] == 1.5
    assert (dest / "a" / study.JOB).exists()
    assert not (dest / "a" / "log_summary.txt").exists()


def test_sound_record_keeps_the_samples_and_their_summary(tmp_path):
    out, dest = tmp_path / "out", tmp_path / "record"
    log = ("LAMMPS (4 Feb 2025)\npacking: 618 grains\nthermo line 1 2 3\n"
           "checks: phi2 0.82\npacking_steps 575000\npulse: t_tof 12\nmoduli: C11 0.005\n  packing: indented\n")
    make_job(out, "p1e-4_H25_s3", log=log)
    make_job(out, "p1e-4_H25_s3_m10_v0", log=log)
    make_job(out, "chain", log=log)
    make_job(out, "lattice_p1e-4_M24", log=log)
    written = study.record_jobs(str(out), str(dest), summarise=sound_study.log_summary,
                                select=sound_study.is_sample)
    assert written == 2
    assert sorted(os.listdir(dest)) == ["p1e-4_H25_s3", "p1e-4_H25_s3_m10_v0"]
    summary = (dest / "p1e-4_H25_s3" / "log_summary.txt").read_text().splitlines()
    assert summary == ["packing: 618 grains", "checks: phi2 0.82", "packing_steps 575000", "pulse: t_tof 12",
                       "moduli: C11 0.005"]


def test_a_job_run_again_keeps_its_record_when_it_measured_the_same(tmp_path):
    out, dest = tmp_path / "out", tmp_path / "record"
    make_job(out, "deposit")
    study.record_jobs(str(out), str(dest))
    recorded = dest / "deposit"
    study.write_job(str(recorded), {"name": "deposit", "recorded_from": "ensemble/log.deposit"})
    (recorded / study.RESULT).write_text('{"value": 1.5, "wall_time": 9}\n')
    study.write_result(str(out / "deposit"), {"value": 1.5, "wall_time": 12})      # the rerun: same grains
    study.record_jobs(str(out), str(dest))
    assert json.loads((recorded / study.JOB).read_text())["recorded_from"] == "ensemble/log.deposit"
    assert json.loads((recorded / study.RESULT).read_text())["wall_time"] == 9
    study.write_result(str(out / "deposit"), {"value": 1.6, "wall_time": 12})      # measured otherwise
    study.record_jobs(str(out), str(dest))
    assert json.loads((recorded / study.RESULT).read_text()) == {"value": 1.6, "wall_time": 12}
    assert "recorded_from" in json.loads((recorded / study.JOB).read_text())     # its settings did not change


def test_sound_record_of_part_of_the_study_keeps_the_full_tables(tmp_path, monkeypatch):
    """study.py record --tables NAME: the tables of an OUT that holds only
    part of the study go to RECORD/NAME; the full study's tables.md stays."""
    from types import SimpleNamespace
    out, dest = tmp_path / "out", tmp_path / "record"
    make_job(out, "p1e-4_H25_s3", log="packing: 618 grains\n")
    dest.mkdir()
    (dest / "tables.md").write_text("the full study\n")
    monkeypatch.setattr(sound_study.sound_collect, "collect",
                        lambda top: (out / "tables.md").write_text("the seeds of out\n"))
    sound_study.record(SimpleNamespace(out=str(out), record=str(dest), tables="tables_part.md"))
    assert (dest / "tables.md").read_text() == "the full study\n"
    assert (dest / "tables_part.md").read_text() == "the seeds of out\n"
    assert (dest / "p1e-4_H25_s3" / study.RESULT).exists()
    with pytest.raises(SystemExit, match="no directory"):
        sound_study.record(SimpleNamespace(out=str(out), record=str(dest), tables="../tables.md"))


def test_a_sample_run_again_keeps_its_whole_record(tmp_path):
    """A sound sample made again bit for bit (its result the same apart from
    wall_seconds) keeps its recorded job.json, result.json and log summary,
    even when today's deck writes one more setting and other paths."""
    out, dest = tmp_path / "out", tmp_path / "record"
    make_job(out, "p1e-4_H25_s1", log="packing: in /old/path\n")
    study.record_jobs(str(out), str(dest), summarise=sound_study.log_summary, select=sound_study.is_sample)
    recorded = dest / "p1e-4_H25_s1"
    (recorded / study.RESULT).write_text('{"value": 1.5, "wall_seconds": 549}\n')
    study.write_job(str(out / "p1e-4_H25_s1"), {"name": "p1e-4_H25_s1", "mu": 0.5})
    study.write_result(str(out / "p1e-4_H25_s1"), {"value": 1.5, "wall_seconds": 114})
    (out / "p1e-4_H25_s1" / "log.lammps").write_text("packing: in /new/path\n")
    written = study.record_jobs(str(out), str(dest), summarise=sound_study.log_summary,
                                select=sound_study.is_sample)
    assert written == 0
    assert json.loads((recorded / study.RESULT).read_text())["wall_seconds"] == 549
    assert "mu" not in json.loads((recorded / study.JOB).read_text())
    assert (recorded / "log_summary.txt").read_text() == "packing: in /old/path\n"


def test_mpirun_leaves_a_single_rank_job_free_to_use_every_core():
    """study.mpirun: a one-rank job sees the cores its parent sees (Open MPI
    would bind it to the first core, and two such jobs side by side, as
    `study.py run --jobs 2` launches them, would share that core)"""
    if shutil.which("mpirun") is None:
        pytest.skip("no mpirun on PATH")
    environment = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    probe = [sys.executable, "-c", "import os; print(sorted(os.sched_getaffinity(0)))"]
    done = subprocess.run(study.mpirun(1) + probe, capture_output=True, text=True, env=environment, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.split("\n")[0] == str(sorted(os.sched_getaffinity(0)))
