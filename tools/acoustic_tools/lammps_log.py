"""Read the thermo output of a LAMMPS log file into numpy arrays.

Each `run` or `minimize` prints a block of thermo lines headed by the names of
its columns ("Step Temp ...") and closed by "Loop time of ...".  read_log()
returns one ThermoBlock per such block, so a deck that runs several times (a
tilt ramp, say) can be analysed run by run.

    python3 -m acoustic_tools.lammps_log log.lammps          # summary of each block
    python3 -m acoustic_tools.lammps_log log.lammps v_theta  # one column, block by block
"""
import sys
from dataclasses import dataclass, field

import numpy as np


@dataclass
class ThermoBlock:
    """One run's thermo output: column names and a (rows x columns) array."""
    columns: list
    data: np.ndarray
    loop_time: float = float("nan")    # "Loop time of X", nan if the run did not finish
    warnings: list = field(default_factory=list)

    def __getitem__(self, name):
        try:
            return self.data[:, self.columns.index(name)]
        except ValueError:
            raise KeyError(f"no thermo column '{name}'; columns are {self.columns}") from None


def _numbers(line, ncolumns):
    parts = line.split()
    if len(parts) != ncolumns:
        return None
    try:
        return [float(p) for p in parts]
    except ValueError:
        return None


def read_log(path):
    """All thermo blocks of a LAMMPS log file, in order."""
    blocks = []
    columns, rows, warnings = None, [], []
    with open(path, errors="replace") as f:
        for line in f:
            stripped = line.strip()
            if stripped.startswith("WARNING"):
                warnings.append(stripped)
            if columns is None:
                words = stripped.split()
                if words and words[0] == "Step" and all(not _is_number(w) for w in words):
                    columns, rows = words, []
                continue
            if stripped.startswith("Loop time of"):
                blocks.append(ThermoBlock(columns, np.array(rows).reshape(-1, len(columns)),
                                          float(stripped.split()[3]), warnings))
                columns, warnings = None, []
                continue
            values = _numbers(stripped, len(columns))
            if values is not None:
                rows.append(values)
    if columns is not None:    # an unfinished run still has its rows
        blocks.append(ThermoBlock(columns, np.array(rows).reshape(-1, len(columns)),
                                  float("nan"), warnings))
    return blocks


def wall_time(path):
    """The "Total wall time: h:mm:ss" of a finished LAMMPS log, in seconds
    (nan if no run finished).  A log that several processes appended to (a
    ramp run as pieces: `log file append`) has one such line per process that
    finished; their sum is returned."""
    total, found = 0, False
    for line in open(path):
        if line.startswith("Total wall time:"):
            h, m, s = (int(v) for v in line.split()[-1].split(":"))
            total, found = total + 3600 * h + 60 * m + s, True
    return total if found else float("nan")


def _is_number(word):
    try:
        float(word)
        return True
    except ValueError:
        return False


def main(argv):
    if len(argv) < 2:
        print(__doc__)
        return 2
    blocks = read_log(argv[1])
    for k, b in enumerate(blocks):
        if len(argv) > 2:
            print(f"block {k}: {argv[2]} =", " ".join(f"{v:g}" for v in b[argv[2]]))
        else:
            print(f"block {k}: {len(b.data)} rows, columns {' '.join(b.columns)}, "
                  f"loop time {b.loop_time:g}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
