"""The I/O contract of SPEC ("Exit status, errors and I/O"), on the installed program.

Every command (its simplest valid invocation) runs as a real process under each condition of
the exit table: stdout closed, stdout on ``/dev/full``, a reader that goes away, every output
encoding, a corrupt / empty / truncated / unwritable / racing unit cache, no ``HOME``,
Ctrl-C. Each case checks the exact exit status, exactly one ``Error:`` line on stderr (or none
where the contract says quiet), no traceback, and the time taken. The processes of one
condition run in parallel (the module takes some 10-20 s).

Statuses: 0 computed, 2 bad input, 3 the output could not be written, 130 interrupted, 141 the
reader went away. Issue 15: before, a vanished reader gave 1, a full or closed stdout
"internal error" (2) or exit 0 with the answer lost, latin-1 failed every table, a bad cache
failed every run, a missing HOME was created, and ``--batch /dev/zero`` never returned.
"""
from __future__ import annotations

import array
import fcntl
import math
import os
import pickle
import signal
import subprocess
import sys
import termios
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

from helpers import on_a_terminal

DYNCALC = Path(sys.executable).parent / "dyncalc"

#: The simplest valid invocation of every command.
COMMANDS = {
    "spring-series": ["spring-series", "200 N/m", "300 N/m"],
    "spring-parallel": ["spring-parallel", "2kN/m", "3kN/m"],
    "natural-frequency": ["natural-frequency", "--k", "100 N/m", "--m", "2kg"],
    "damping-ratio": ["damping-ratio", "--decrement", "0.23"],
    "rolling-onset": ["rolling-onset", "--v0", "5 m/s", "--mu", "0.3"],
    "coriolis": ["coriolis", "--omega", "2 rad/s", "--vr", "3 m/s"],
    "forced-response": ["forced-response", "--k", "100 N/m", "--m", "2kg", "--F0", "1 N",
                        "--Omega", "3 rad/s"],
    "modes": ["modes", "--M", "2, 0; 0, 1 kg", "--K", "300, -100; -100, 100 N/m"],
    "inertia": ["inertia", "disk(m=2kg, r=0.1m)", "-disk(m=0.5kg, r=5cm)"],
    "rigid-body": ["rigid-body", "--scene", "drum-two-blocks", "m1=20kg", "m2=15kg", "r1=0.2m",
                   "r2=0.4m", "J_A=2kg*m^2"],
    "eom": ["eom", "--coords", "x", "--T", "m*x'^2/2", "--V", "k*x^2/2", "m=2kg", "k=2N/m"],
    "scenes": ["scenes"],
}
#: Seconds one case may take: a one-off answers in well under a second (0.2 s warm, 0.6 s
#: with a cold unit cache); the margin is for a loaded machine running the cases in parallel.
SLOW = 10.0

CLOSED_MESSAGE = "Error: cannot write the output: standard output is closed"
FULL_MESSAGE = "Error: cannot write the output: No space left on device"


@pytest.fixture(scope="module")
def warm_cache(tmp_path_factory):
    """A unit cache folder filled by one run (the cases then start warm)."""
    folder = tmp_path_factory.mktemp("cache")
    run(["spring-series", "1 N/m"], cache=folder)
    return folder


def test_the_cache_goes_where_dyncalc_cache_dir_says(tmp_path):
    folder = tmp_path / "cache"
    # mixed units: the full path, which reads pint's registry (the quick path reads none)
    done = run(["spring-series", "1 N/m", "2 N/mm"], cache=folder)
    assert (done.returncode, done.stderr) == (0, b"")
    assert list(folder.glob("*.pickle")), "the run wrote no cache"


def env_for(cache=None, **changes) -> dict[str, str]:
    """This environment without the variables that change dyncalc's output, with the unit
    cache in ``cache`` and ``changes`` applied (None removes a variable)."""
    env = {k: v for k, v in os.environ.items()
           if not k.startswith(("DYNCALC_", "PYTHONIOENCODING", "NO_COLOR", "FORCE_COLOR",
                                "COLUMNS"))}
    if cache is not None:
        env["DYNCALC_CACHE_DIR"] = str(cache)
    for key, value in changes.items():
        if value is None:
            env.pop(key, None)
        else:
            env[key] = value
    return env


def run(args, *, cache=None, stdout=subprocess.PIPE, stdin=subprocess.DEVNULL, shell_redirect="",
        env=None, input_bytes=None):
    """Run ``dyncalc ARGS``; ``shell_redirect`` (``>&-``) is applied by ``sh`` around it."""
    env = env if env is not None else env_for(cache)
    argv = [str(DYNCALC), *args]
    if shell_redirect:
        argv = ["sh", "-c", f'exec "$@" {shell_redirect}', "sh", *argv]
    start = time.perf_counter()
    done = subprocess.run(argv, stdout=stdout, stderr=subprocess.PIPE,
                          stdin=None if input_bytes is not None else stdin, env=env,
                          input=input_bytes, timeout=60)
    done.seconds = time.perf_counter() - start
    return done


def in_parallel(function, items):
    with ThreadPoolExecutor(max_workers=min(8, 2 * (os.cpu_count() or 1))) as pool:
        return dict(zip(items, pool.map(function, items)))


def error_lines(stderr: bytes) -> list[str]:
    text = stderr.decode("utf-8", "replace")
    assert "Traceback" not in text, text
    return [line for line in text.splitlines() if line.strip()]


# --- stdout closed, full, or its reader gone ---------------------------------------------------

def test_stdout_closed_is_status_3_with_one_error_line(warm_cache):
    """``dyncalc ... >&-``: nothing can be written, so not 0 (the answer would be lost)."""
    cases = {**COMMANDS, "--value": COMMANDS["natural-frequency"] + ["--value", "f"],
             "--json": COMMANDS["natural-frequency"] + ["--json"],
             "--help": ["--help"]}
    done = in_parallel(lambda name: run(cases[name], cache=warm_cache, shell_redirect=">&-"),
                       list(cases))
    for name, result in done.items():
        assert (result.returncode, error_lines(result.stderr)) == (3, [CLOSED_MESSAGE]), name
        assert result.seconds < SLOW, name


def test_stdout_on_dev_full_is_status_3_with_one_error_line(warm_cache):
    cases = {**COMMANDS, "--value": COMMANDS["natural-frequency"] + ["--value", "f"]}

    def full(name):
        with open("/dev/full", "wb") as sink:
            return run(cases[name], cache=warm_cache, stdout=sink)

    for name, result in in_parallel(full, list(cases)).items():
        assert (result.returncode, error_lines(result.stderr)) == (3, [FULL_MESSAGE]), name
        assert result.seconds < SLOW, name


def _reader_gone(args, cache):
    """Run with stdout a pipe whose read end is closed at once (``dyncalc scenes | true``)."""
    read, write = os.pipe()
    os.close(read)
    try:
        start = time.perf_counter()
        proc = subprocess.run([str(DYNCALC), *args], stdout=write, stderr=subprocess.PIPE,
                              stdin=subprocess.DEVNULL, env=env_for(cache), timeout=60)
        proc.seconds = time.perf_counter() - start
        return proc
    finally:
        os.close(write)


def test_a_reader_that_goes_away_is_status_141_and_quiet(warm_cache):
    """As coreutils end (``yes | head -1``): 128 + SIGPIPE, nothing on stderr (was 1, the
    status reserved for a failed --check)."""
    cases = {**COMMANDS, "--help": ["--help"], "--json": COMMANDS["scenes"] + ["--json"]}
    done = in_parallel(lambda name: _reader_gone(cases[name], warm_cache), list(cases))
    for name, result in done.items():
        assert (result.returncode, result.stderr) == (141, b""), name
        assert result.seconds < SLOW, name


# --- encodings ---------------------------------------------------------------------------------

@pytest.mark.parametrize("encoding", ["latin-1", "ascii", "utf-8"])
def test_every_encoding_prints_every_command(warm_cache, encoding):
    """Symbols the encoding cannot carry fall back to ASCII names; nothing fails (latin-1
    failed every table with "internal error")."""
    cases = {**COMMANDS,
             "uncertain": ["natural-frequency", "--k", "100 N/m ± 2 N/m", "--m", "2kg"]}
    env = env_for(warm_cache, PYTHONIOENCODING=encoding)
    done = in_parallel(lambda name: run(cases[name], env=env), list(cases))
    for name, result in done.items():
        assert (result.returncode, result.stderr) == (0, b""), (name, result.stderr)
        text = result.stdout.decode(encoding)  # the bytes are in the encoding asked for
        assert text.strip(), name
    table = done["uncertain"].stdout.decode(encoding).splitlines()
    omega = math.sqrt(100 / 2)
    symbol = "ω" if encoding == "utf-8" else "omega"
    plus_minus = "+/-" if encoding == "ascii" else "±"
    assert table[2].split() == ["omega", symbol, f"{omega:.6g}", plus_minus, "0.071", "rad/s"]
    # the columns stay aligned on the replaced symbols
    assert len({line.index("rad/s") for line in table[2:3]}) == 1
    assert table[1].index("unit") == table[2].index("rad/s")


@pytest.mark.parametrize("encoding, shown", [("ascii", "+/-"), ("latin-1", "±")])
def test_an_error_message_in_every_encoding(warm_cache, encoding, shown):
    result = run(["natural-frequency", "--k", "100N/m ± x", "--m", "1kg"],
                 env=env_for(warm_cache, PYTHONIOENCODING=encoding))
    assert result.returncode == 2
    lines = result.stderr.decode(encoding).splitlines()
    assert len(lines) == 1 and lines[0].startswith("Error: --k: cannot read '100N/m " + shown)


# --- the unit cache ----------------------------------------------------------------------------

#: The commands of the cache cases: the registry (and so its cache) is the same for every
#: command; these two read quantities, scalars and vectors, with a cold start each.
CACHE_COMMANDS = ("natural-frequency", "coriolis")


def _answers(cache, env=None):
    """The cache commands run at once with the cache in ``cache``; their results by name."""
    env = env or env_for(cache)
    return in_parallel(lambda name: run(COMMANDS[name], env=env), CACHE_COMMANDS)


def _assert_all_ran(done):
    for name, result in done.items():
        assert (result.returncode, result.stderr) == (0, b""), (name, result.stderr)
        assert result.seconds < SLOW, name


def _cache_files_are_whole(folder):
    files = list(folder.glob("*.pickle"))
    assert files
    for file in files:
        with open(file, "rb") as f:
            pickle.load(f)  # a whole pickle again
    assert not list(folder.glob(".tmp-*")), "a temporary file was left behind"


@pytest.mark.parametrize("damage", ["empty", "truncated", "corrupt", "wrong object"])
def test_a_damaged_cache_is_ignored_and_rebuilt(tmp_path, warm_cache, damage):
    folder = tmp_path / "cache"
    folder.mkdir()
    for file in warm_cache.glob("*.pickle"):
        data = file.read_bytes()
        damaged = {"empty": b"", "truncated": data[: len(data) // 2],
                   "corrupt": bytes(range(256)) * 4,
                   "wrong object": pickle.dumps(1)}[damage]
        (folder / file.name).write_bytes(damaged)
    _assert_all_ran(_answers(folder))
    _cache_files_are_whole(folder)


def test_racing_first_runs_on_an_empty_cache(tmp_path):
    """Six processes start together on an empty cache: each reads a whole file or none."""
    folder = tmp_path / "cache"
    folder.mkdir()
    env = env_for(folder)
    # --strict-units: the full path, which builds pint's registry (the quick path of
    # dyncalc.quick answers the plain one-off without it and writes no cache)
    args = COMMANDS["natural-frequency"] + ["--value", "f", "--strict-units"]
    done = in_parallel(lambda i: run(args, env=env), list(range(6)))
    for result in done.values():
        assert (result.returncode, result.stderr) == (0, b""), result.stderr
        assert float(result.stdout) == pytest.approx(math.sqrt(50) / (2 * math.pi), rel=1e-15)
    _cache_files_are_whole(folder)


def test_an_unwritable_cache_folder(tmp_path, warm_cache):
    """A folder that cannot be written: read when it has the files, else run without."""
    if os.geteuid() == 0:  # root writes through any mode bits; /proc takes no new files
        unwritable = Path("/proc")
        _assert_all_ran(_answers(unwritable))
        return
    filled, empty = tmp_path / "filled", tmp_path / "empty"
    filled.mkdir()
    empty.mkdir()
    for file in warm_cache.glob("*.pickle"):
        (filled / file.name).write_bytes(file.read_bytes())
    for folder in (filled, empty):
        folder.chmod(0o555)
        try:
            _assert_all_ran(_answers(folder))
            assert not list(empty.iterdir())
        finally:
            folder.chmod(0o755)


def test_a_missing_home_is_not_created(tmp_path):
    home = tmp_path / "no-such-home"
    env = env_for(None, HOME=str(home), XDG_CACHE_HOME=None)
    _assert_all_ran(_answers(None, env))
    assert not home.exists()


def test_no_home_variable_at_all(tmp_path):
    env = env_for(None, HOME=None, XDG_CACHE_HOME=str(tmp_path / "xdg"))
    _assert_all_ran(_answers(None, env))
    assert list((tmp_path / "xdg" / "dyncalc").glob("*.pickle"))


def test_an_empty_cache_variable_runs_without_a_cache(tmp_path):
    env = env_for(None, DYNCALC_CACHE_DIR="", HOME=str(tmp_path), XDG_CACHE_HOME=None)
    _assert_all_ran(_answers(None, env))
    assert not list(tmp_path.iterdir())


# --- batch: closed streams, binary sources, Ctrl-C ---------------------------------------------

BATCH = ["natural-frequency", "--batch", "-"]
ROWS = b"k [N/m],m [kg]\n100,2\n"


def test_batch_with_stdin_closed(warm_cache):
    result = run(BATCH, cache=warm_cache, shell_redirect="<&-")
    assert result.returncode == 2
    assert error_lines(result.stderr) == [
        "Error: line 1: reading the file failed: standard input is closed"]


def test_batch_with_stdout_closed(warm_cache):
    result = run(BATCH, cache=warm_cache, stdin=subprocess.PIPE, input_bytes=ROWS,
                 shell_redirect=">&-")
    assert (result.returncode, error_lines(result.stderr)) == (3, [CLOSED_MESSAGE])


def test_batch_on_dev_full(warm_cache):
    with open("/dev/full", "wb") as sink:
        result = run(BATCH, cache=warm_cache, stdin=subprocess.PIPE, input_bytes=ROWS,
                     stdout=sink)
    assert (result.returncode, error_lines(result.stderr)) == (3, [FULL_MESSAGE])


@pytest.mark.parametrize("command", [c for c in COMMANDS if c != "scenes"])
def test_batch_from_dev_zero_is_refused_at_once(warm_cache, command):
    """``--batch /dev/zero`` read forever (a line that never ends)."""
    scene = ["--scene", "pendulum"] if command == "eom" else []  # eom batches a scene's rows
    result = run([command, *scene, "--batch", "/dev/zero"], cache=warm_cache)
    assert result.returncode == 2 and result.seconds < SLOW
    assert error_lines(result.stderr) == [
        "Error: line 1: the line is longer than 100000 characters and holds NUL bytes: this "
        "is not a CSV text file"]


def test_batch_from_an_endless_line_is_refused(warm_cache):
    endless = b"1" * (1 << 25)  # 32 MB without a line end
    result = run(BATCH, cache=warm_cache, stdin=subprocess.PIPE, input_bytes=endless)
    assert result.returncode == 2 and result.seconds < SLOW
    assert error_lines(result.stderr) == [
        f"Error: line 1: the line is longer than {1 << 24} characters: this is not a CSV text "
        "file"]


def _pending(fd: int) -> int:
    """Bytes written to a pipe and not yet read by the other end."""
    size = array.array("i", [0])
    fcntl.ioctl(fd, termios.FIONREAD, size)
    return size[0]


@pytest.mark.parametrize("command", ["natural-frequency", "spring-series"])
def test_ctrl_c_during_a_batch_is_status_130_without_traceback(warm_cache, command):
    """A batch read from a slow pipe, interrupted once it has read the first rows."""
    header = b"k [N/m],m [kg]\n100,2\n" if command == "natural-frequency" else b"k1,k2\n1,2\n"
    # Ctrl-C's default restored in the child: a suite started in the background by a shell
    # without job control inherits SIGINT ignored, and then so would the program (rightly)
    proc = subprocess.Popen([str(DYNCALC), command, "--batch", "-"], stdin=subprocess.PIPE,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            env=env_for(warm_cache),
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    proc.stdin.write(header)
    proc.stdin.flush()
    deadline = time.monotonic() + 30
    while _pending(proc.stdin.fileno()) and time.monotonic() < deadline:
        time.sleep(0.02)  # the program has started and is reading the batch
    time.sleep(0.1)
    start = time.perf_counter()
    proc.send_signal(signal.SIGINT)
    status = proc.wait(timeout=30)
    assert time.perf_counter() - start < SLOW
    stderr = proc.stderr.read()
    proc.stdin.close()
    assert status == 130
    assert error_lines(stderr) == ["Error: interrupted"]


# --- messages and usage ------------------------------------------------------------------------

def test_bare_dyncalc_prints_its_help(warm_cache):
    result = run([], cache=warm_cache)
    assert (result.returncode, result.stderr) == (0, b"")
    assert result.stdout.decode().startswith("Usage: dyncalc [OPTIONS] COMMAND [ARGS]...\n")
    assert b"natural-frequency" in result.stdout


def test_a_misspelt_command_gets_did_you_mean(warm_cache):
    result = run(["natral-frequency"], cache=warm_cache)
    assert result.returncode == 2
    assert error_lines(result.stderr) == [
        "Error: No such command 'natral-frequency' (did you mean 'natural-frequency'?); see "
        "'dyncalc --help'"]


def _on_a_terminal(args, columns: str):
    """Run with stdout a pseudo-terminal ``columns`` wide (``COLUMNS``); what it printed."""
    status, out, err = on_a_terminal([str(DYNCALC), *args], env_for(None, COLUMNS=columns))
    return status, out.decode(), err


@pytest.mark.parametrize("columns", ["30", "33", "36", "0", "abc"])
def test_a_narrow_terminal_never_cuts_a_number(columns):
    """On a terminal 30-36 columns wide rich cut the numbers (5.7006…); with ``COLUMNS=0``
    it printed nothing, exit 0."""
    args = ["natural-frequency", "--k", "100 N/m ± 2 N/m", "--m", "3.077kg"]
    status, out, err = _on_a_terminal(args, columns)
    assert (status, err) == (0, b"")
    omega = math.sqrt(100 / 3.077)
    for number in (f"{omega:.6g}", f"{omega / (2 * math.pi):.6g}",
                   f"{2 * math.pi / omega:.6g}"):
        assert number in out, (number, out)
    assert "…" not in out


# --- options given twice -----------------------------------------------------------------------

def _every_single_option():
    """(command, flag, is a flag) of every option of every command that is not repeatable."""
    import click

    from dyncalc.cli import cli

    for name in sorted(cli.commands):
        for param in cli.commands[name].params:
            if not isinstance(param, click.Option) or param.multiple or not param.expose_value:
                continue
            flag = max(param.opts, key=len)
            yield name, flag, param.is_flag


@pytest.mark.parametrize("command, flag, is_flag", list(_every_single_option()))
def test_an_option_given_twice_is_refused(command, flag, is_flag):
    """``--k 100N/m --k 200N/m`` kept the last silently; every option of every command,
    ``--batch`` included, is now refused when given twice (in-process: 200 cases)."""
    from click.testing import CliRunner

    from dyncalc.cli import cli

    twice = [flag, flag] if is_flag else [flag, "1", flag, "2"]
    result = CliRunner().invoke(cli, [*COMMANDS[command], *twice])
    assert result.exit_code == 2, (result.stdout, result.stderr)
    assert result.stderr == f"Error: {flag} given twice: give it once\n"


def test_value_is_repeatable_one_number_a_line(warm_cache):
    result = run(COMMANDS["natural-frequency"] + ["--value", "f", "--value", "omega",
                                                  "--value", "T"], cache=warm_cache)
    assert result.returncode == 0
    omega = math.sqrt(100 / 2)
    assert [float(x) for x in result.stdout.split()] == pytest.approx(
        [omega / (2 * math.pi), omega, 2 * math.pi / omega], rel=1e-15)


def test_the_same_result_named_twice_by_unit_is_refused(warm_cache):
    result = run(COMMANDS["spring-series"] + ["--unit", "k_eq=N/mm", "--unit", "k_eq=N/m"],
                 cache=warm_cache)
    assert result.returncode == 2
    assert error_lines(result.stderr) == ["Error: --unit k_eq= given twice: give it once"]
