"""Readers of LAMMPS's text outputs other than the log (acoustic_tools.lammps_log):
dumps, the files of fix ave/time and fix ave/chunk, and the "name value"
files that the decks write with print.

  read_dump             text dump custom (ITEM: ATOMS) or dump local (ITEM:
                        ENTRIES), all snapshots: list of Snapshot
  read_ave_time         fix ave/time, scalar mode: dict column -> array
  read_ave_time_vector  fix ave/time, vector mode: list of (step, rows)
  read_ave_chunk        fix ave/chunk: list of (step, dict column -> array)
  read_key_values       name value pairs: dict name -> float (or string)

A block or snapshot cut short at the end of a file (a job still running or
killed) is dropped.  numpy only.
"""
from dataclasses import dataclass, field

import numpy as np

INTEGER_COLUMNS = ("id", "type", "mol", "proc", "procp1")


@dataclass
class Snapshot:
    """One snapshot of a dump: timestep, box (3 x 2, lo/hi per axis; zeros
    when the dump has no box) and the columns by name.  snapshot[name] is a
    column by its dump name, snapshot[k] (an int) the k-th column."""
    timestep: int
    box: np.ndarray
    columns: dict = field(default_factory=dict)

    def __getitem__(self, key):
        if isinstance(key, (int, np.integer)):
            return list(self.columns.values())[key]
        try:
            return self.columns[key]
        except KeyError:
            raise KeyError(f"no column '{key}' in the dump; columns are {list(self.columns)}") from None

    def __contains__(self, name):
        return name in self.columns

    def __len__(self):
        return len(next(iter(self.columns.values()))) if self.columns else 0


def _skip_item(lines, k):
    """index of the next 'ITEM:' line after line k"""
    k += 1
    while k < len(lines) and not lines[k].startswith("ITEM:"):
        k += 1
    return k


def read_dump(path):
    """All snapshots of a text dump custom or dump local: list of Snapshot.

    Each snapshot is "ITEM: TIMESTEP", the step, "ITEM: NUMBER OF ATOMS"
    (or ENTRIES), the count, "ITEM: BOX BOUNDS ..." and its three lines,
    then "ITEM: ATOMS col1 col2 ..." (or ENTRIES) and count rows; other
    ITEMs (TIME, UNITS) are skipped and a snapshot may have no row.  The
    rows of all snapshots with the same columns are converted at once (fast
    on 1e5 snapshots).  Columns id, type, mol, proc, procp1 are integers,
    the others floats."""
    with open(path) as handle:
        lines = handle.read().splitlines()
    snaps = []                      # (step, box, column names, first row, count)
    step, count, box, k, n = None, 0, np.zeros((3, 2)), 0, len(lines)
    while k < n:
        line = lines[k]
        if line.startswith("ITEM: TIMESTEP"):
            step = int(lines[k + 1].split()[0])
            box = np.zeros((3, 2))
            k += 2
        elif line.startswith("ITEM: NUMBER OF"):
            count = int(lines[k + 1])
            k += 2
        elif line.startswith("ITEM: BOX BOUNDS"):
            box = np.array([[float(v) for v in lines[k + 1 + a].split()[:2]] for a in range(3)])
            k += 4
        elif line.startswith("ITEM: ATOMS") or line.startswith("ITEM: ENTRIES"):
            if k + 1 + count > n:
                break
            snaps.append((step, box, tuple(line.split()[2:]), k + 1, count))
            k += 1 + count
        else:
            k = _skip_item(lines, k)
    parsed = [None] * len(snaps)
    for names in dict.fromkeys(s[2] for s in snaps):
        members = [i for i, s in enumerate(snaps) if s[2] == names]
        rows = [row for i in members for row in lines[snaps[i][3]:snaps[i][3] + snaps[i][4]]]
        data = np.loadtxt(rows, ndmin=2, comments=None) if rows else np.zeros((0, len(names)))
        if data.shape[1] != len(names):
            raise ValueError(f"{path}: {data.shape[1]} values per row for columns {names}")
        columns = [np.rint(data[:, c]).astype(np.int64) if name in INTEGER_COLUMNS else data[:, c]
                   for c, name in enumerate(names)]
        bounds = np.cumsum([0] + [snaps[i][4] for i in members])
        for j, i in enumerate(members):
            lo, hi = bounds[j], bounds[j + 1]
            parsed[i] = Snapshot(snaps[i][0], snaps[i][1],
                                 {name: col[lo:hi] for name, col in zip(names, columns)})
    return parsed


def read_ave_time(path):
    """A fix ave/time file in scalar mode: dict column name -> array.

    Lines starting with '#' are comments; the last comment line before the
    first data line names the columns ("# TimeStep name1 name2 ..."; a
    title2 of the user's is taken as it is).  Extra header words beyond the
    number of data columns are dropped, missing ones are named c<k>.  The
    first column is also available as 'TimeStep' (integers)."""
    with open(path) as handle:
        lines = handle.read().splitlines()
    header, rows = None, []
    for line in lines:
        if line.startswith("#"):
            if not rows:
                header = line
        elif line.strip():
            rows.append(line)
    names = header.lstrip("#").split() if header else []
    if not rows:
        return {name: np.zeros(0) for name in names} | {"TimeStep": np.zeros(0, dtype=np.int64)}
    data = np.loadtxt(rows, ndmin=2, comments=None)
    ncol = data.shape[1]
    names = names[:ncol] + [f"c{k}" for k in range(len(names), ncol)]
    columns = {name: data[:, k] for k, name in enumerate(names)}
    columns["TimeStep"] = np.rint(data[:, 0]).astype(np.int64)
    return columns


def read_ave_time_vector(path):
    """The blocks of a fix ave/time ... mode vector file: list of (step,
    rows), rows a 2D array of the values after the row index."""
    with open(path) as handle:
        lines = [line.split() for line in handle if line.strip() and not line.startswith("#")]
    blocks, k = [], 0
    while k < len(lines):
        step, nrows = int(lines[k][0]), int(lines[k][1])
        if k + 1 + nrows > len(lines):
            break
        rows = np.array([[float(v) for v in line[1:]] for line in lines[k + 1:k + 1 + nrows]])
        blocks.append((step, rows))
        k += 1 + nrows
    return blocks


def read_ave_chunk(path):
    """A fix ave/chunk file: list of (timestep, dict column -> array).

    Format: three comment lines, the third naming the columns of the rows
    ("# Chunk Coord1 Coord2 Ncount name ..."; "# Chunk OrigID ..." with
    compress yes), then blocks of a line "timestep nchunks total-count"
    followed by nchunks rows.  'Chunk' (and 'OrigID') are integers."""
    with open(path) as handle:
        lines = handle.read().splitlines()
    comments = [line for line in lines if line.startswith("#")]
    if len(comments) < 3:
        raise ValueError(f"{path}: expected the 3 comment lines of fix ave/chunk")
    names = comments[2].lstrip("#").split()
    data = [line for line in lines if line.strip() and not line.startswith("#")]
    blocks, k = [], 0
    while k < len(data):
        words = data[k].split()
        step, nchunk = int(words[0]), int(words[1])
        rows = data[k + 1:k + 1 + nchunk]
        if len(rows) < nchunk:
            break
        values = np.loadtxt(rows, ndmin=2, comments=None) if nchunk else np.zeros((0, len(names)))
        if values.shape[1] != len(names):
            raise ValueError(f"{path}: {values.shape[1]} columns in the block of step {step}, "
                             f"header names {len(names)}")
        columns = {name: values[:, c] for c, name in enumerate(names)}
        for name in ("Chunk", "OrigID"):
            if name in columns:
                columns[name] = np.rint(columns[name]).astype(np.int64)
        blocks.append((step, columns))
        k += 1 + nchunk
    return blocks


def read_key_values(path):
    """The "name value" pairs of a file that a deck writes with print, one
    or more pairs per line (examples/sound's summary.txt, moduli.txt and
    checks.txt, examples/cavity's TAG.params): dict name -> value, a float
    where the value reads as one, else the string."""
    values = {}
    with open(path) as handle:
        for line in handle:
            words = line.split()
            for name, value in zip(words[::2], words[1::2]):
                try:
                    values[name] = float(value)
                except ValueError:
                    values[name] = value
    return values
