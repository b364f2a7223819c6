"""The files of one job of a study, and the command line of a study.

A study (examples/avalanche, examples/sound, examples/cavity) runs many jobs,
each a LAMMPS run in a directory of its own:

  job.json     the job's settings (the -var values of the deck, and anything
               else the run command chose), written by the study's `run`
               command before LAMMPS starts; collect reads the settings from
               here, never from the directory's name
  result.json  what the deck measured, one JSON object written by the deck
               itself with LAMMPS's `print \"\"\"{...}\"\"\" file ${dir}/result.json`
               at its end; a job without it has not finished

Each study has one entry point, `examples/<study>/study`, with the
subcommands `run`, `collect` and `figures` (see `main`).
"""
import argparse
import concurrent.futures
import json
import math
import os
import shutil
import subprocess

JOB = "job.json"
RESULT = "result.json"


def write_job(directory, settings):
    """Write the settings of a job (a dict of JSON values) to directory/job.json."""
    os.makedirs(directory, exist_ok=True)
    with open(os.path.join(directory, JOB), "w") as handle:
        json.dump(settings, handle, indent=1, sort_keys=True)
        handle.write("\n")


def read_job(directory):
    """The settings of the job in directory (a dict); KeyError-free: {} when absent."""
    path = os.path.join(directory, JOB)
    if not os.path.exists(path):
        return {}
    with open(path) as handle:
        return json.load(handle)


def _finite_or_none(value):
    return None if isinstance(value, float) and not math.isfinite(value) else value


def _load_result(path):
    """result.json as written, the non-finite numbers LAMMPS prints (nan,
    inf) read as floats"""
    with open(path) as handle:
        text = handle.read()
    for word, token in (("-nan", "NaN"), ("nan", "NaN"), ("-inf", "-Infinity"), ("inf", "Infinity")):
        text = text.replace(f": {word}", f": {token}")
    return json.loads(text)


def read_result(directory):
    """What the deck of the job in directory measured (a dict), or None when the
    job has not written its result.json (not run, still running, or failed).
    The non-finite numbers LAMMPS prints (nan, inf) become None."""
    path = os.path.join(directory, RESULT)
    if not os.path.exists(path):
        return None
    result = _load_result(path)
    return {key: _finite_or_none(value) for key, value in result.items()}


def write_result(directory, result):
    """Write result.json from Python (a conversion of older outputs; the decks
    write their own); non-finite numbers as JSON's NaN, Infinity"""
    with open(os.path.join(directory, RESULT), "w") as handle:
        json.dump(result, handle, indent=1)
        handle.write("\n")


def add_to_result(directory, values):
    """Add values (a dict) to the result.json of the job in directory, after
    the deck's own: what the run command measured around the deck, e.g. the
    job's wall time"""
    result = _load_result(os.path.join(directory, RESULT))
    result.update(values)
    write_result(directory, result)


def finished_jobs(out):
    """(directory, settings, result) of every finished job under out, in the
    order of the directories' names (one level: out/<job>/)."""
    if not os.path.isdir(out):
        return []
    found = []
    for name in sorted(os.listdir(out)):
        directory = os.path.join(out, name)
        if not os.path.isdir(directory):
            continue
        result = read_result(directory)
        if result is not None:
            found.append((directory, read_job(directory), result))
    return found


def record_jobs(out, dest, files=(JOB, RESULT), summarise=None, select=None):
    """Copy `files` of every finished job under out (that select(name)
    accepts, if given) into dest/<job>/, and, with summarise, write what
    summarise(directory) returns as dest/<job>/log_summary.txt.  A job present
    in both whose result measured the same (same_measurement) keeps its
    record as it was (its provenance, wall time and log summary: a rerun
    bit for bit the same adds nothing); otherwise each file is written again
    from out unless it holds the same.  One recorded earlier and absent from
    out is kept.  Returns the number of jobs written."""
    written = 0
    for directory, _, _ in finished_jobs(out):
        name = os.path.basename(directory)
        if select is not None and not select(name):
            continue
        target = os.path.join(dest, name)
        if same_measurement(os.path.join(target, RESULT), os.path.join(directory, RESULT)):
            continue
        os.makedirs(target, exist_ok=True)
        for file in files:
            source, recorded = os.path.join(directory, file), os.path.join(target, file)
            if os.path.exists(source) and not same_measurement(recorded, source):
                shutil.copyfile(source, recorded)
        if summarise is not None:
            with open(os.path.join(target, "log_summary.txt"), "w") as f:
                f.write(summarise(directory))
        written += 1
    return written


# what a rerun of a job may change without changing what it measured: where
# the record first came from, and how long the run took (the avalanche study
# writes wall_time, the sound study wall_seconds)
BOOKKEEPING = ("recorded_from", "wall_time", "wall_seconds")


def same_measurement(recorded, source):
    """Whether the JSON file `recorded` (in a record) holds what `source`
    (the same file of a finished job) holds, apart from BOOKKEEPING.  A job
    run again (a deposit or ramp rerun for its t_con runs, bit for bit the
    same) then leaves its record as it was; anything else is False."""
    if not (recorded.endswith(".json") and os.path.exists(recorded)):
        return False
    try:
        with open(recorded) as old, open(source) as new:
            old, new = json.load(old), json.load(new)
    except ValueError:
        return False
    if not (isinstance(old, dict) and isinstance(new, dict)):
        return old == new

    def measured(values):
        return {key: value for key, value in values.items() if key not in BOOKKEEPING}
    return measured(old) == measured(new)


def lammps_variables(settings, names):
    """The -var arguments of LAMMPS's command line for the given settings."""
    arguments = []
    for name in names:
        arguments += ["-var", name, str(settings[name])]
    return arguments


def mpirun(ranks):
    """The launcher of one LAMMPS job on `ranks` MPI ranks: mpirun -np N,
    and with Open MPI --oversubscribe (more ranks than cores is allowed) and
    --bind-to none.  Open MPI binds the ranks of every mpirun to the cores
    counted from the first, so jobs launched side by side (run --jobs 2, each
    on one rank) would all share the first core and each run at half speed;
    unbound, the kernel spreads them over the free cores."""
    launcher = ["mpirun", "-np", str(ranks)]
    version = subprocess.run(["mpirun", "--version"], capture_output=True, text=True)
    if "Open MPI" in version.stdout + version.stderr:
        launcher += ["--oversubscribe", "--bind-to", "none"]
    return launcher


def run_jobs(run_one, jobs, workers):
    """run_one(*job) for every job, `workers` at a time (each one a LAMMPS
    process), printing what each returns as it finishes."""
    with concurrent.futures.ThreadPoolExecutor(max_workers=workers) as pool:
        running = [pool.submit(run_one, *job) for job in jobs]
        for finished in concurrent.futures.as_completed(running):
            print(finished.result(), flush=True)


def main(description, commands, argv=None):
    """The command line of a study: commands maps each subcommand's name
    ("run", "collect", "figures", ...) to (function, help, add_arguments),
    where add_arguments(parser) declares its options and function(args) does
    the work."""
    parser = argparse.ArgumentParser(description=description)
    subparsers = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for name, (function, help_text, add_arguments) in commands.items():
        sub = subparsers.add_parser(name, help=help_text, description=help_text)
        add_arguments(sub)
        sub.set_defaults(function=function)
    args = parser.parse_args(argv)
    return args.function(args)
