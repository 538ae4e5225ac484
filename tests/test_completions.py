"""Shell completion: the committed scripts match the generator, bash really completes with them,
and a completion request stays light (completion runs the program on every TAB)."""
from __future__ import annotations

import importlib.util
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
from importlib.metadata import version
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
COMPLETIONS = ROOT / "completions"
COMPLETE_VAR = "_DYNCALC_COMPLETE"
COMMANDS = {"spring-series", "spring-parallel", "natural-frequency", "damping-ratio",
            "rolling-onset", "coriolis", "scenes"}
HEAVY = ("pint", "numpy", "scipy", "rich")
BIN_DIR = Path(sys.executable).parent


@pytest.fixture(scope="module")
def gen():
    spec = importlib.util.spec_from_file_location("gen_completions",
                                                  ROOT / "tools" / "gen_completions.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _env(**extra) -> dict[str, str]:
    """This environment with the venv's bin first on PATH (so ``dyncalc`` is the installed
    console script) and no completion variables left over from the caller."""
    env = {k: v for k, v in os.environ.items()
           if k not in (COMPLETE_VAR, "COMP_WORDS", "COMP_CWORD")}
    env["PATH"] = str(BIN_DIR) + os.pathsep + env.get("PATH", "")
    env.update(extra)
    return env


# --- the committed files ----------------------------------------------------------------------

def test_committed_scripts_match_the_generator(gen):
    scripts = gen.generate()
    assert sorted(scripts) == ["dyncalc.bash", "dyncalc.fish", "dyncalc.zsh"]
    for name, text in scripts.items():
        path = COMPLETIONS / name
        assert path.is_file(), (
            f"completions/{name} is missing; run `python tools/gen_completions.py`")
        assert path.read_bytes() == text.encode("utf-8"), (
            f"completions/{name} differs from what the click app generates (click "
            f"{version('click')}); run `python tools/gen_completions.py` and commit the result")


def test_generated_scripts_are_deterministic(gen):
    first, second = gen.generate(), gen.generate()
    assert first == second
    for name, text in first.items():
        assert str(ROOT) not in text and str(BIN_DIR) not in text, name
        assert "\r" not in text, name
        assert text.endswith("\n"), name


def test_check_flags_a_stale_file(gen, tmp_path):
    for name, text in gen.generate().items():
        (tmp_path / name).write_bytes(text.encode("utf-8"))
    assert gen.check(tmp_path) == []
    (tmp_path / "dyncalc.fish").write_text("# stale\n")
    (tmp_path / "dyncalc.zsh").unlink()
    assert gen.check(tmp_path) == ["dyncalc.zsh", "dyncalc.fish"]


def test_check_flag_exit_status():
    run = subprocess.run([sys.executable, "tools/gen_completions.py", "--check"], cwd=ROOT,
                         env=_env(), capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr


@pytest.mark.parametrize("shell", ["zsh", "fish"])
def test_zsh_and_fish_scripts_call_back_dyncalc(shell):
    text = (COMPLETIONS / f"dyncalc.{shell}").read_text()
    assert COMPLETE_VAR in text
    assert f"{COMPLETE_VAR}={shell}_complete" in text
    assert re.search(r"\bdyncalc\b", text)
    if shell == "zsh":  # compinit reads the tag on the first line of a file on $fpath
        assert text.startswith("#compdef dyncalc\n")


def test_bash_script_syntax():
    """bash parses the script (zsh and fish are not on these machines: their scripts are
    checked for content above; `zsh -n` / `fish --no-execute` check them where installed)."""
    run = subprocess.run(["bash", "-n", str(COMPLETIONS / "dyncalc.bash")],
                         capture_output=True, text=True, timeout=30)
    assert run.returncode == 0, run.stderr


# --- real bash ---------------------------------------------------------------------------------

def _bash_version() -> tuple[int, int] | None:
    bash = shutil.which("bash")
    if bash is None:
        return None
    out = subprocess.run([bash, "--norc", "--noprofile", "-c",
                          'echo "${BASH_VERSINFO[0]} ${BASH_VERSINFO[1]}"'],
                         capture_output=True, text=True, timeout=30).stdout.split()
    return int(out[0]), int(out[1])


def bash_complete(*words: str) -> list[str]:
    """What bash offers for ``words`` (the last one is the word being completed), found the way
    bash does it: source the script, look up the function ``complete -F`` registered for
    dyncalc, set COMP_WORDS/COMP_CWORD and call it with (command, word, previous word)."""
    have = _bash_version()
    if have is None:
        pytest.skip("bash is not installed")
    if have < (4, 4):
        pytest.skip(f"click's bash completion needs bash >= 4.4; this is {have[0]}.{have[1]}")
    assert shutil.which("dyncalc", path=str(BIN_DIR)), (
        f"no dyncalc console script next to {sys.executable}; run `pip install -e .`")
    array = " ".join(shlex.quote(w) for w in words)
    script = f"""
set -u
source {shlex.quote(str(COMPLETIONS / "dyncalc.bash"))}
spec=$(complete -p dyncalc) || exit 3
func=$(sed -E 's/.* -F ([^ ]+) .*/\\1/' <<< "$spec")
COMP_WORDS=({array}); COMP_CWORD=$(( ${{#COMP_WORDS[@]}} - 1 ))
COMP_LINE="${{COMP_WORDS[*]}}"; COMP_POINT=${{#COMP_LINE}}
COMPREPLY=()
"$func" dyncalc "${{COMP_WORDS[COMP_CWORD]}}" "${{COMP_WORDS[COMP_CWORD-1]}}"
printf '%s\\n' "${{COMPREPLY[@]}}"
"""
    run = subprocess.run(["bash", "--norc", "--noprofile", "-c", script], env=_env(),
                         capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, f"bash exited {run.returncode}: {run.stderr}"
    assert run.stderr == "", run.stderr
    return [line for line in run.stdout.splitlines() if line]


def test_bash_registers_a_completion_function():
    if _bash_version() is None:
        pytest.skip("bash is not installed")
    run = subprocess.run(["bash", "--norc", "--noprofile", "-c",
                          f"source {shlex.quote(str(COMPLETIONS / 'dyncalc.bash'))}; "
                          "complete -p dyncalc"], capture_output=True, text=True, timeout=30)
    assert run.returncode == 0, run.stderr
    assert "-F _dyncalc_completion dyncalc" in run.stdout


def test_bash_completes_a_command_prefix():
    offered = bash_complete("dyncalc", "spring-s")
    assert "spring-series" in offered
    assert "spring-parallel" not in offered


def test_bash_completes_every_command():
    offered = bash_complete("dyncalc", "")
    assert COMMANDS <= set(offered), f"missing: {sorted(COMMANDS - set(offered))}"


def test_bash_completes_an_option():
    assert "--check" in bash_complete("dyncalc", "spring-series", "--ch")


# --- the scenes NAME argument ------------------------------------------------------------------

def test_scene_names_complete(monkeypatch):
    from click.shell_completion import get_completion_class

    import dyncalc.scenes
    from dyncalc.cli import cli

    monkeypatch.setattr(dyncalc.scenes, "scene_names",
                        lambda: ["mass-spring", "pendulum", "mass-on-beam"])
    complete = get_completion_class("bash")(cli, {}, "dyncalc", COMPLETE_VAR)
    assert [c.value for c in complete.get_completions(["scenes"], "mass")] == [
        "mass-spring", "mass-on-beam"]
    assert [c.value for c in complete.get_completions(["scenes"], "")] == [
        "mass-spring", "pendulum", "mass-on-beam"]


# --- start-up weight ---------------------------------------------------------------------------

_REQUESTS = [("bash_complete", "dyncalc spring-", 1),
             ("bash_complete", "dyncalc ", 1),
             ("bash_complete", "dyncalc spring-series --ch", 2),
             ("bash_complete", "dyncalc spring-parallel --digits ", 3),
             ("bash_complete", "dyncalc scenes ", 2),
             ("zsh_complete", "dyncalc spring-series --", 2)]

_PROBE = f"""
import json, os, sys
import dyncalc.cli

heavy = lambda: sorted(m for m in {HEAVY!r} if m in sys.modules)
report = {{"import": heavy(), "complete": []}}
for instruction, words, cword in {_REQUESTS!r}:
    os.environ.update({COMPLETE_VAR}=instruction, COMP_WORDS=words, COMP_CWORD=str(cword))
    try:
        dyncalc.cli.main([])
    except SystemExit as exc:
        status = exc.code
    else:
        status = "no exit"
    report["complete"].append([words, status, heavy()])
print()
print(json.dumps(report))
"""


def test_import_and_completion_stay_light():
    run = subprocess.run([sys.executable, "-c", _PROBE], env=_env(), capture_output=True,
                         text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    report = json.loads(run.stdout.splitlines()[-1])
    assert report["import"] == [], f"importing dyncalc.cli imports {report['import']}"
    for words, status, heavy in report["complete"]:
        assert status in (0, None), f"completing {words!r} exited {status}"
        assert heavy == [], f"completing {words!r} imports {heavy}"
    assert "plain,spring-series" in run.stdout


def test_console_script_completion_stays_light():
    """The process the shell actually starts on TAB: the installed ``dyncalc`` script."""
    run = subprocess.run([str(BIN_DIR / "dyncalc")], env=_env(**{COMPLETE_VAR: "bash_complete",
                                                  "COMP_WORDS": "dyncalc spring-",
                                                  "COMP_CWORD": "1",
                                                  "PYTHONPROFILEIMPORTTIME": "1"}),
                         capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    assert {"plain,spring-parallel", "plain,spring-series"} <= set(run.stdout.split())
    imported = {line.rsplit("|", 1)[-1].strip().split(".")[0]
                for line in run.stderr.splitlines() if line.startswith("import time:")}
    assert "click" in imported  # the import-time report is there at all
    assert not imported & set(HEAVY), f"completion imports {sorted(imported & set(HEAVY))}"
