"""acoustic_tools.lammps_log on small synthetic logs with known content."""
import math

import numpy as np
import pytest

from acoustic_tools.lammps_log import read_log

LOG = """LAMMPS (29 Sep 2021 - Update 2)
units lj
Per MPI rank memory allocation (min/avg/max) = 5.1 | 5.1 | 5.1 Mbytes
Step KinEng c_nc v_theta
       0            0      1.5 0.5
     500    1.5149293      2.25 0.5
    1000   0.60037063        3 0.5
Loop time of 0.0880726 on 1 procs for 1000 steps with 384 atoms

WARNING: Something odd (src/thermo.cpp:1)
Step KinEng c_nc v_theta
    1000   0.60037063        3 1.0
    1500   -1.5e-3           4 1.0
Loop time of 1.5 on 2 procs for 500 steps with 384 atoms
Step KinEng c_nc v_theta
    1500   1            4 1.5
    1600   2            4 1.5
"""


@pytest.fixture
def logfile(tmp_path):
    path = tmp_path / "log.lammps"
    path.write_text(LOG)
    return path


def test_blocks_columns_and_values(logfile):
    blocks = read_log(logfile)
    assert len(blocks) == 3
    assert blocks[0].columns == ["Step", "KinEng", "c_nc", "v_theta"]
    np.testing.assert_array_equal(blocks[0]["Step"], [0, 500, 1000])
    np.testing.assert_allclose(blocks[0]["KinEng"], [0.0, 1.5149293, 0.60037063])
    assert blocks[0].loop_time == pytest.approx(0.0880726)
    np.testing.assert_allclose(blocks[1]["KinEng"], [0.60037063, -1.5e-3])
    assert blocks[1].warnings == ["WARNING: Something odd (src/thermo.cpp:1)"]


def test_unfinished_run_is_kept(logfile):
    last = read_log(logfile)[-1]
    assert math.isnan(last.loop_time)
    np.testing.assert_array_equal(last["Step"], [1500, 1600])


def test_unknown_column_names_the_columns(logfile):
    with pytest.raises(KeyError, match="no thermo column 'Temp'"):
        read_log(logfile)[0]["Temp"]


def test_wall_time(tmp_path):
    from acoustic_tools.lammps_log import wall_time
    done = tmp_path / "done.log"
    done.write_text("Loop time of 1.5 on 2 procs for 10 steps with 4 atoms\nTotal wall time: 1:02:03\n")
    assert wall_time(done) == 3723
    cut = tmp_path / "cut.log"
    cut.write_text("Loop time of 1.5 on 2 procs for 10 steps with 4 atoms\n")
    assert wall_time(cut) != wall_time(cut)        # nan: the run did not finish
    pieces = tmp_path / "pieces.log"
    pieces.write_text("Total wall time: 0:00:30\nLoop time of 1.5 on 2 procs for 10 steps with 4 atoms\n"
                      "Total wall time: 0:01:00\n")
    assert wall_time(pieces) == 90
