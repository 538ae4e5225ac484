"""Shared test helpers: run a dyncalc command in-process and read what it printed."""
import json

from click.testing import CliRunner

from dyncalc.cli import cli


def invoke(*args):
    """``dyncalc ARGS`` through the real group (its one-line errors and exit codes)."""
    return CliRunner().invoke(cli, list(args))


def json_of(*args):
    """The JSON object ``dyncalc ARGS --json`` prints (asserting exit 0)."""
    result = invoke(*args, "--json")
    assert result.exit_code == 0, result.stderr
    return json.loads(result.stdout)


def error_line(result):
    """The one stderr line of a refusal, asserting exit 2 and no traceback."""
    assert result.exit_code == 2, (result.stdout, result.stderr)
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and "Traceback" not in result.stderr, result.stderr
    return lines[0]


def count_readings(monkeypatch, *modules, name="parse_quantity"):
    """Count the texts the given modules read: their ``name`` (``parse_quantity``) is wrapped
    so that each call appends its text to the list returned (the read-once tests of issue
    14: propagation must never read a text again)."""
    calls = []
    for module in modules:
        original = getattr(module, name)

        def counting(*args, _original=original, **kwargs):
            calls.append(args[0])
            return _original(*args, **kwargs)

        monkeypatch.setattr(module, name, counting)
    return calls


def on_a_terminal(argv: list[str], env: dict[str, str]) -> tuple[int, bytes, bytes]:
    """Run ``argv`` with its stdout a pseudo-terminal (stdin empty) and ``env``; (exit status,
    what the terminal received, stderr)."""
    import os
    import pty
    import subprocess

    master, slave = pty.openpty()
    proc = subprocess.Popen(argv, stdout=slave, stderr=subprocess.PIPE,
                            stdin=subprocess.DEVNULL, env=env)
    os.close(slave)
    chunks = []
    while True:
        try:
            chunk = os.read(master, 65536)
        except OSError:  # the terminal closed with the process
            break
        if not chunk:
            break
        chunks.append(chunk)
    os.close(master)
    return proc.wait(timeout=60), b"".join(chunks), proc.stderr.read()


def batch_run(args, stdin):
    """``dyncalc ARGS`` in-process with ``stdin`` as its standard input (a batch read from
    ``-``)."""
    return CliRunner().invoke(cli, list(args), input=stdin)


def fast_same_as_generic(monkeypatch, args, stdin):
    """The batch run of ``args`` on the vectorised path, asserting the same exit status,
    stdout and stderr as the generic (one-off a row) path (``DYNCALC_BATCH_GENERIC=1``)."""
    from dyncalc.batch import GENERIC_ENV

    fast = batch_run(args, stdin)
    monkeypatch.setenv(GENERIC_ENV, "1")
    generic = batch_run(args, stdin)
    monkeypatch.delenv(GENERIC_ENV)
    assert (fast.exit_code, fast.stdout, fast.stderr) == (
        generic.exit_code, generic.stdout, generic.stderr)
    return fast


def count_block_rows(monkeypatch, module, name: str = "_solved") -> list:
    """The number of rows of each block ``module.name`` returns (it is wrapped): how many
    rows a vectorised path took."""
    counts = []
    original = getattr(module, name)

    def counting(*args):
        blocks = original(*args)
        counts.extend(len(block.rows) for block in blocks)
        return blocks

    monkeypatch.setattr(module, name, counting)
    return counts


def eom_batch(path, scene: str, as_json: bool, fast: bool, calls=None, about=None):
    """``(status, stdout, stderr)`` of ``eom --scene SCENE --batch PATH`` in-process (``fast``:
    the vectorised path allowed); ``calls`` (a list) gets the cells of every row the one-off
    answers."""
    import io

    from dyncalc.batch import run_batch
    from dyncalc.batch.rows import EomRows

    spec = EomRows(scene=scene, about=about)
    if calls is not None:
        compute = spec.compute

        def counted(texts, labels):
            calls.append(texts)
            return compute(texts, labels)
        spec.compute = counted
    out, err = io.StringIO(), io.StringIO()
    status = run_batch(spec, str(path), as_json=as_json, on_error="skip", out=out, err=err,
                       fast=fast)
    return status, out.getvalue(), err.getvalue()


def eom_batch_without_sympy(scene: str, path) -> str:
    """The stdout of ``dyncalc eom --scene SCENE --batch PATH`` in a fresh interpreter,
    after checking that it exits 0 and never imported sympy."""
    import subprocess
    import sys

    code = ("import sys\nfrom dyncalc.cli import cli\n"
            "try:\n    cli(['eom', '--scene', sys.argv[1], '--batch', sys.argv[2]])\n"
            "except SystemExit as e:\n    assert not e.code, e.code\n"
            "print('sympy' in sys.modules, file=sys.stderr)\n")
    done = subprocess.run([sys.executable, "-c", code, scene, str(path)], capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stderr.strip().splitlines()[-1] == "False"
    return done.stdout
