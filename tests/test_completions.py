"""Shell completion: the installed program prints click's script for bash, zsh and fish (the
README's one-liners), each shell really completes with it (the custom completions included),
and a completion request stays light (completion runs the program on every TAB)."""
from __future__ import annotations

import json
import os
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
COMPLETE_VAR = "_DYNCALC_COMPLETE"
COMMANDS = {"spring-series", "spring-parallel", "natural-frequency", "damping-ratio",
            "rolling-onset", "coriolis", "forced-response", "modes", "scenes"}
HEAVY = ("pint", "numpy", "scipy", "rich")
BIN_DIR = Path(sys.executable).parent


def _env(**extra) -> dict[str, str]:
    """This environment with the venv's bin first on PATH (so ``dyncalc`` is the installed
    console script) and no completion variables left over from the caller."""
    env = {k: v for k, v in os.environ.items()
           if k not in (COMPLETE_VAR, "COMP_WORDS", "COMP_CWORD")}
    env["PATH"] = str(BIN_DIR) + os.pathsep + env.get("PATH", "")
    env.update(extra)
    return env


# --- the scripts, from the installed program -----------------------------------------------

SHELL_CHECK = {"bash": ["bash", "-n"], "zsh": ["zsh", "-n"], "fish": ["fish", "--no-execute"]}


def need(shell: str) -> str:
    """The path of ``shell``, or a skip that says how to get it (``.ci/run`` installs all
    three from Debian's packages)."""
    path = shutil.which(shell)
    if path is None:
        pytest.skip(f"{shell} is not installed (apt-get install {shell}; .ci/run does)")
    return path


def source(shell: str) -> str:
    """The completion script the installed ``dyncalc`` prints for ``shell`` (what the README's
    one-liners evaluate)."""
    run = subprocess.run([str(BIN_DIR / "dyncalc")],
                         env=_env(**{COMPLETE_VAR: f"{shell}_source"}),
                         capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    return run.stdout


@pytest.mark.parametrize("shell", ["bash", "zsh", "fish"])
def test_the_program_prints_a_script_its_shell_parses(shell, tmp_path):
    text = source(shell)
    assert f"{COMPLETE_VAR}={shell}_complete" in text
    assert re.search(r"\bdyncalc\b", text)
    assert str(ROOT) not in text and "\r" not in text
    need(shell)
    script = tmp_path / f"dyncalc.{shell}"
    script.write_text(text)
    run = subprocess.run([*SHELL_CHECK[shell], str(script)], capture_output=True, text=True,
                         timeout=30)
    assert run.returncode == 0, run.stderr


def test_no_committed_scripts_left():
    """The scripts come from click at install time; none is kept by hand in the repository."""
    assert not (ROOT / "completions").exists()
    assert not (ROOT / "tools" / "gen_completions.py").exists()


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
    need("bash")
    have = _bash_version()
    if have < (4, 4):
        pytest.skip(f"click's bash completion needs bash >= 4.4; this is {have[0]}.{have[1]}")
    assert shutil.which("dyncalc", path=str(BIN_DIR)), (
        f"no dyncalc console script next to {sys.executable}; run `pip install -e .`")
    array = " ".join(shlex.quote(w) for w in words)
    script = f"""
set -u
eval "$({COMPLETE_VAR}=bash_source dyncalc)"
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
    need("bash")
    run = subprocess.run(["bash", "--norc", "--noprofile", "-c",
                          f'eval "$({COMPLETE_VAR}=bash_source dyncalc)"; complete -p dyncalc'],
                         env=_env(), capture_output=True, text=True, timeout=30)
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


def test_bash_completes_what_click_cannot_guess():
    assert bash_complete("dyncalc", "damping-ratio", "--scene", "") == [
        "pendulum-spring-dashpot", "rod-in-fluid", "frame-brace-damper"]
    assert bash_complete("dyncalc", "spring-series", "--unit", "k_eq=") == [
        "k_eq=N/m", "k_eq=N/mm", "k_eq=kN/m", "k_eq=lbf/in"]
    assert bash_complete("dyncalc", "natural-frequency", "--scene", "pendulum", "--method",
                         "s") == ["small-angle", "series"]


# --- real zsh and fish -------------------------------------------------------------------------

def zsh_complete(*words: str) -> list[str]:
    """What zsh's completion function (the script the program prints, unchanged) adds for
    ``words``, run in a real zsh outside the line editor: ``compadd``/``_describe`` print what
    they are given, ``_path_files`` prints ``<files>``."""
    need("zsh")
    array = " ".join(shlex.quote(w) for w in words)
    script = f"""
compdef() {{ : }}
compadd() {{ print -l -- "${{(@P)${{@[-1]}}}}" }}
_describe() {{ local item; for item in "${{(@P)3}}"; do print -- "${{item%%:*}}"; done }}
_path_files() {{ print -- "<files>" }}
eval "$({COMPLETE_VAR}=zsh_source dyncalc)"
words=({array}); CURRENT=${{#words}}
_dyncalc_completion
"""
    run = subprocess.run(["zsh", "-f", "-c", script], env=_env(), capture_output=True,
                         text=True, timeout=60)
    assert run.returncode == 0, f"zsh exited {run.returncode}: {run.stderr}"
    assert run.stderr == "", run.stderr
    return [line for line in run.stdout.splitlines() if line]


def fish_complete(line: str, cwd: Path) -> list[str]:
    """What fish offers for the command line ``line`` (``complete -C``), with the script the
    program prints sourced, in ``cwd``."""
    need("fish")
    script = (f"{COMPLETE_VAR}=fish_source dyncalc | source; "
              f"complete -C {shlex.quote(line)}")
    run = subprocess.run(["fish", "--no-config", "-c", script], env=_env(), cwd=cwd,
                         capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, f"fish exited {run.returncode}: {run.stderr}"
    assert run.stderr == "", run.stderr
    return [line.split("\t")[0] for line in run.stdout.splitlines() if line]


def test_zsh_completes():
    assert {"spring-series", "spring-parallel"} <= set(zsh_complete("dyncalc", "spring-"))
    assert zsh_complete("dyncalc", "damping-ratio", "--scene", "rod") == ["rod-in-fluid"]
    assert zsh_complete("dyncalc", "natural-frequency", "--unit", "T=m") == ["T=ms", "T=min"]
    assert zsh_complete("dyncalc", "natural-frequency", "--batch", "ro") == ["<files>"]


def test_fish_completes(tmp_path):
    (tmp_path / "rows.csv").write_text("k [N/m],m [kg]\n100,2\n")
    assert fish_complete("dyncalc spring-s", tmp_path) == ["spring-series"]
    assert fish_complete("dyncalc damping-ratio --scene fr", tmp_path) == [
        "frame-brace-damper"]
    assert fish_complete("dyncalc rolling-onset --value t", tmp_path) == ["t_roll"]
    assert fish_complete("dyncalc natural-frequency --batch ro", tmp_path) == ["rows.csv"]


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
             ("bash_complete", "dyncalc natural-frequency --scene ", 3),
             ("bash_complete", "dyncalc natural-frequency --scene pendulum --method ", 5),
             ("bash_complete", "dyncalc natural-frequency --unit T=", 3),
             ("bash_complete", "dyncalc damping-ratio --scene ", 3),
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
