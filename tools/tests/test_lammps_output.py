"""acoustic_tools.lammps_output on small files written as LAMMPS writes them:
dumps (custom and local, with and without atoms, orthogonal and triclinic
boxes, a last snapshot cut short) and the files of fix ave/time (scalar and
vector mode) and fix ave/chunk."""
import numpy as np
import pytest

from acoustic_tools import lammps_output as lo

BOX = "ITEM: BOX BOUNDS pp ff pp\n-1e-03 5.1e-02\n-1e-03 4.4e-02\n-1e-03 1e-03\n"
TRICLINIC = "ITEM: BOX BOUNDS xy xz yz pp ff pp\n-2 5 0.5\n-1 4 0\n-1 1 0\n"


def test_dump_custom_many_snapshots(tmp_path):
    text = ("ITEM: TIMESTEP\n100\nITEM: NUMBER OF ATOMS\n2\n" + BOX +
            "ITEM: ATOMS id v_ycontact v_fwall\n7 0.0125 1.5e-3\n12 0.02 2\n"
            "ITEM: TIMESTEP\n200\nITEM: NUMBER OF ATOMS\n0\n" + BOX +
            "ITEM: ATOMS id v_ycontact v_fwall\n"
            "ITEM: TIMESTEP\n300\nITEM: NUMBER OF ATOMS\n1\n" + TRICLINIC +
            "ITEM: ATOMS id v_ycontact v_fwall\n3 0.001 4\n"
            "ITEM: TIMESTEP\n400\nITEM: NUMBER OF ATOMS\n3\n" + BOX +
            "ITEM: ATOMS id v_ycontact v_fwall\n1 0.1 1\n")     # cut short: dropped
    path = tmp_path / "cavity.contacts"
    path.write_text(text)
    snaps = lo.read_dump(path)
    assert [s.timestep for s in snaps] == [100, 200, 300]
    assert list(snaps[0]["id"]) == [7, 12] and snaps[0]["id"].dtype.kind == "i"
    assert list(snaps[0]["v_fwall"]) == [1.5e-3, 2.0]
    np.testing.assert_array_equal(snaps[0].box, [[-1e-3, 5.1e-2], [-1e-3, 4.4e-2], [-1e-3, 1e-3]])
    assert len(snaps[1]) == 0 and set(snaps[1].columns) == {"id", "v_ycontact", "v_fwall"}
    assert list(snaps[2]["v_ycontact"]) == [0.001]
    np.testing.assert_array_equal(snaps[2].box, [[-2, 5], [-1, 4], [-1, 1]])   # tilt factors left out


def test_dump_local_by_name_and_by_position(tmp_path):
    path = tmp_path / "c.dump"
    path.write_text("ITEM: TIMESTEP\n5\nITEM: NUMBER OF ENTRIES\n2\nITEM: BOX BOUNDS pp fm pp\n"
                    "0 1\n0 2\n0 3\nITEM: ENTRIES c_a[1] c_a[2]\n1 2\n3 4\n")
    (snap,) = lo.read_dump(path)
    assert list(snap["c_a[1]"]) == [1.0, 3.0]
    assert list(snap[1]) == [2.0, 4.0] and list(snap[-1]) == [2.0, 4.0]
    assert "c_a[2]" in snap and "id" not in snap and len(snap) == 2
    with pytest.raises(KeyError, match="columns are"):
        snap["id"]


def test_dump_items_time_and_units_are_skipped(tmp_path):
    path = tmp_path / "t.dump"
    path.write_text("ITEM: UNITS\nsi\nITEM: TIME\n0.5\nITEM: TIMESTEP\n9\nITEM: NUMBER OF ATOMS\n1\n" + BOX +
                    "ITEM: ATOMS id type x\n4 2 0.25\n")
    (snap,) = lo.read_dump(path)
    assert snap.timestep == 9 and snap["type"].dtype.kind == "i" and list(snap["x"]) == [0.25]


def test_ave_time_scalar(tmp_path):
    path = tmp_path / "f.txt"
    path.write_text("# Time-averaged data for fix wallrec\n# TimeStep c_ftotal v_h\n"
                    "100 1.5 0.03\n200 -2 3e-2\n300 4.25e+06 0.031\n")
    data = lo.read_ave_time(path)
    assert list(data["TimeStep"]) == [100, 200, 300]
    assert data["TimeStep"].dtype.kind == "i"
    assert list(data["c_ftotal"]) == [1.5, -2.0, 4.25e6]
    assert list(data["v_h"]) == [0.03, 0.03, 0.031]
    # a user's title2 with words after the names (in.cavity's "(dt ... s)"),
    # and a single record
    path.write_text("# cavity run\n# time-step F F_1 F_2 (dt 1e-06 s)\n5 3 1 2\n")
    data = lo.read_ave_time(path)
    assert set(data) == {"time-step", "F", "F_1", "F_2", "TimeStep"}
    assert list(data["F_2"]) == [2.0] and list(data["TimeStep"]) == [5]


def test_ave_time_vector_blocks(tmp_path):
    path = tmp_path / "modes.hist"
    path.write_text("# Time-averaged data for fix hist\n# TimeStep Number-of-rows\n# Row c_h[1] c_h[2]\n"
                    "0 2\n1 0 5\n2 1 6\n100 3\n1 500 0.0004\n2 1500 0.0004\n3 2500 0.0002\n"
                    "200 3\n1 500 0.1\n")                          # cut short: dropped
    blocks = lo.read_ave_time_vector(path)
    assert [step for step, _ in blocks] == [0, 100]
    np.testing.assert_array_equal(blocks[0][1], [[0, 5], [1, 6]])
    np.testing.assert_allclose(blocks[-1][1][:, 0], [500, 1500, 2500])


def test_ave_chunk_blocks(tmp_path):
    path = tmp_path / "c.txt"
    path.write_text("# Chunk-averaged data for fix flow and group all\n"
                    "# Timestep Number-of-chunks Total-count\n"
                    "# Chunk Coord1 Coord2 Ncount vx vy\n"
                    "10 3 4\n  1 0.5 0.5 3 1 -1\n  2 0.5 1.5 1 2 0\n  3 1.5 0.5 0 0 0\n"
                    "20 3 4\n  1 0.5 0.5 1 5 1\n  2 0.5 1.5 3 6 0\n  3 1.5 0.5 0 0 0\n"
                    "30 3 2\n  1 0.5 0.5")                    # a block cut short
    blocks = lo.read_ave_chunk(path)
    assert [step for step, _ in blocks] == [10, 20]
    assert list(blocks[1][1]["Chunk"]) == [1, 2, 3] and blocks[1][1]["Chunk"].dtype.kind == "i"
    assert list(blocks[0][1]["Coord2"]) == [0.5, 1.5, 0.5]
    assert list(blocks[1][1]["vx"]) == [5.0, 6.0, 0.0]
    path.write_text("# one comment line only\n10 1 1\n 1 0.5 0.5 1 0 0\n")
    with pytest.raises(ValueError, match="3 comment lines"):
        lo.read_ave_chunk(path)
