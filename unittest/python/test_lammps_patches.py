"""The patches of LAMMPS itself (cmake/patches/*.patch, doc/lammps-doc-index.patch)
apply to the LAMMPS source they are written for, and the LAMMPS-only
reproducer of the two GRANULAR bug fixes (cmake/patches/tests/) gives the
right answer on the patched LAMMPS built here.  With ACOUSTIC_UNPATCHED_LMP
set to an lmp built from the unpatched source (GRANULAR package), the
reproducer must show both defects there."""
import glob
import os
import re
import subprocess

import pytest

LMP = os.environ.get("ACOUSTIC_LMP", "lmp")
SOURCE = os.environ.get("ACOUSTIC_LAMMPS_SOURCE", "")
UNPATCHED = os.environ.get("ACOUSTIC_UNPATCHED_LMP", "")
TOP = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
PATCHES = sorted(glob.glob(os.path.join(TOP, "cmake", "patches", "*.patch"))) + \
    [os.path.join(TOP, "doc", "lammps-doc-index.patch")]
DECK = os.path.join(TOP, "cmake", "patches", "tests", "in.contact-histories-restart")


@pytest.mark.skipif(not SOURCE, reason="ACOUSTIC_LAMMPS_SOURCE (the unpatched LAMMPS source) not given")
@pytest.mark.parametrize("patch", PATCHES, ids=[os.path.basename(p) for p in PATCHES])
def test_patch_applies_to_the_lammps_source(patch):
    done = subprocess.run(["patch", "-p1", "--dry-run", "--forward", "-i", patch], cwd=SOURCE,
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stdout + done.stderr


def reproduce(lmp, tmp_path, write):
    """the deck's lines on 2 ranks: {stage: (tangential force sum, contacts)}"""
    command = ["mpirun", "-np", "2", "--oversubscribe", lmp, "-in", DECK, "-log", "none", "-echo", "none",
               "-nocite", "-screen", str(tmp_path / f"screen{write}"), "-var", "write", str(write),
               "-var", "restart", str(tmp_path / "r.restart")]
    done = subprocess.run(command, cwd=tmp_path, capture_output=True, text=True, timeout=600)
    screen = (tmp_path / f"screen{write}").read_text()
    assert done.returncode == 0, screen + done.stderr
    return dict((m[0], (float(m[1]), int(m[2]))) for m in
                re.findall(r"^(after|restored): tangential (\S+) contacts (\d+)$", screen, re.M))


def test_contact_histories_survive_write_and_read_restart(tmp_path):
    straight = reproduce(LMP, tmp_path, 0)["after"]
    found = reproduce(LMP, tmp_path, 1)
    tangential, contacts = straight
    assert contacts > 200 and tangential > 0.0
    # write_restart between runs leaves the histories as they were, bit for bit
    assert found["after"] == straight
    # read_restart, pair_style not repeated: every contact found, same histories
    assert found["restored"][1] == contacts
    assert found["restored"][0] == pytest.approx(tangential, rel=1e-10)


@pytest.mark.skipif(not UNPATCHED, reason="ACOUSTIC_UNPATCHED_LMP not given")
def test_unpatched_lammps_shows_both_defects(tmp_path):
    straight = reproduce(UNPATCHED, tmp_path, 0)["after"]
    found = reproduce(UNPATCHED, tmp_path, 1)
    assert found["after"][0] != straight[0]          # histories scrambled by write_restart
    assert found["restored"][1] < straight[1]        # contacts missed after read_restart
