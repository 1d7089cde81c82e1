"""Every code block of the project's Markdown runs: python blocks are executed, shell commands run with short
budgets, JSON and YAML samples parse (the rules: tests/docs/doc_blocks.py and tests/docs/doc_commands.py).

A README command that crashes, a Python sample that no longer matches the API, or a JSON sample that does not
parse fails here. Blocks that train or otherwise take long are slow tests (``-m slow``) run with tiny budgets.
"""
from __future__ import annotations

import importlib.metadata
import json
import os
import re
import shlex
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
import yaml

from doc_commands import CONSOLE_SCRIPTS, DEFAULT_TIMEOUT, Rule, rule_for
from doc_blocks import LANGS, Block, commands, read_blocks

ROOT = Path(__file__).resolve().parents[2]
#: The Markdown files whose blocks run.
DOCS = ["README.md", "agents/README.md", *sorted(p.relative_to(ROOT).as_posix() for p in (ROOT / "docs").rglob("*.md")),
        "configs/envs/README.md"]
#: Copied into each sandbox (their code writes next to itself: run folders, reports); the rest is linked.
COPIED = ("agents", "benchmarks", "docs")
LINKED = ("configs", "examples", "tests", "scripts", "pyproject.toml")
#: Seconds the python blocks of one file may take together (each file's blocks run in one process).
PYTHON_TIMEOUT = 600.0


def _all_blocks() -> list[Block]:
    return [b for doc in DOCS for b in read_blocks(ROOT / doc, ROOT)]


BLOCKS = _all_blocks()
SHELL = [b for b in BLOCKS if b.lang in ("bash", "sh", "shell")]
DATA = [b for b in BLOCKS if b.lang in ("json", "yaml")]


# --- the sandbox --------------------------------------------------------------------------------------------
def make_sandbox(tmp: Path) -> Path:
    """A folder that looks like the repository root to the docs' commands; what they write stays in it."""
    box = tmp / "repo"
    box.mkdir()
    for name in COPIED:
        shutil.copytree(ROOT / name, box / name, ignore=shutil.ignore_patterns("__pycache__"))
    for name in LINKED:
        (box / name).symlink_to(ROOT / name)
    return box


def _env() -> dict[str, str]:
    env = dict(os.environ)
    env.update(SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy", PYTHONPATH=str(ROOT), MPLBACKEND="Agg",
               PYTHONWARNINGS="ignore")
    env.pop("BILLIARDS_ALLOW_HEADLESS", None)
    return env


def _python(venv: str) -> str:
    """The interpreter of ``venv`` (the one running the tests for ``.venv``), or skip where it is absent (fail
    with BILLIARDS_REQUIRE_CLIENTS set, as scripts/test.sh does once it has made them)."""
    if venv == ".venv":
        return sys.executable
    exe = ROOT / venv / "bin" / "python"
    if not exe.exists():
        option = venv.removeprefix(".venv-")
        message = f"needs {venv} (bash scripts/setup.sh --{option} makes it; CI has it)"
        if os.environ.get("BILLIARDS_REQUIRE_CLIENTS"):
            pytest.fail(message)
        pytest.skip(message)
    return str(exe)


# --- commands -------------------------------------------------------------------------------------------------
def prepare(command: str, box: Path) -> tuple[str, Rule | None]:
    """The command as the test runs it: console scripts as modules, its rule applied, placeholders filled."""
    for script, module in CONSOLE_SCRIPTS.items():
        command = re.sub(rf"(^|&& |; )\b{re.escape(script)}\b", rf"\1python -m {module}", command)
    rule = rule_for(command)
    if rule is not None:
        command = rule.apply(command)
    if "runs/<run>" in command:
        runs = sorted((p for p in (box / "runs").glob("*") if (p / "run.json").exists()),
                      key=lambda p: p.stat().st_mtime)
        assert runs, f"{command}: runs/<run> stands for a run folder, but no command before it made one"
        command = command.replace("runs/<run>", f"runs/{runs[-1].name}")
    return command, rule


def run_group(args: list[str], timeout: float, **kwargs) -> subprocess.CompletedProcess:
    """``subprocess.run(args, capture_output=True, text=True, stdin=DEVNULL, timeout=timeout, **kwargs)`` in a
    process group of its own, killed whole on a timeout (a command's worker processes included: none is left
    running after a failed test)."""
    proc = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            stdin=subprocess.DEVNULL, start_new_session=True, **kwargs)
    try:
        out, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired as exc:
        os.killpg(proc.pid, signal.SIGKILL)
        out, err = proc.communicate()
        raise subprocess.TimeoutExpired(args, timeout, output=out, stderr=err) from exc
    return subprocess.CompletedProcess(args, proc.returncode, out, err)


def run_command(command: str, box: Path, where: str, venv: str | None = None) -> None:
    """Run one docs command in the sandbox as its rule says (in ``venv`` if given: a block of RLlib commands runs
    wholly in the RLlib venv, as the README's reader has activated it); fail with its output if it does not do as
    written."""
    command, rule = prepare(command, box)
    rule = rule or Rule("", "no rule: as written")
    if rule.kind == "pip":
        check_install(command, where, venv)
        return
    python = _python(venv or rule.venv)
    if rule.cwd == "root" and rule.venv == ".venv" and "scripts/" in command and not (ROOT / ".venv").exists():
        pytest.skip(f"{command}: no .venv in this checkout (scripts/setup.sh makes it; CI has one)")
    if rule.cwd == "root" and "--rllib" in command and not (ROOT / ".venv-rllib").exists():
        pytest.skip(f"{command}: no .venv-rllib in this checkout (CI has one)")
    bindir = str(Path(python).parent)
    env = _env()
    env["PATH"] = f"{bindir}{os.pathsep}{env.get('PATH', '')}"
    env["VIRTUAL_ENV"] = str(Path(python).parent.parent)
    cwd = ROOT if rule.cwd == "root" else box
    shell = command.replace("python -m ", f"{shlex.quote(python)} -m ").replace("python -c ",
                                                                                   f"{shlex.quote(python)} -c ")
    if rule.kind == "server":
        run_server(shell, cwd, env, rule, where)
        return
    started = time.perf_counter()
    try:
        proc = run_group(["bash", "-c", shell], rule.timeout, cwd=cwd, env=env)
    except subprocess.TimeoutExpired as exc:
        out = (exc.stdout or b"")[-2000:] if isinstance(exc.stdout, bytes) else (exc.stdout or "")[-2000:]
        pytest.fail(f"{where}: `{command}` did not finish within {rule.timeout:.0f} s ({rule.why}); if it is "
                    f"meant to take long, give it a budget in tests/docs/doc_commands.py\n{out}")
    took = time.perf_counter() - started
    if proc.returncode != rule.expect:
        pytest.fail(f"{where}: `{command}` exited with status {proc.returncode} after {took:.0f} s "
                    f"({rule.why})\n--- stdout (end)\n{proc.stdout[-3000:]}\n--- stderr (end)\n{proc.stderr[-3000:]}")


def run_server(shell: str, cwd: Path, env: dict[str, str], rule: Rule, where: str) -> None:
    """Start a server command, wait until its output says it is up, stop it."""
    proc = subprocess.Popen(["bash", "-c", f"exec {shell}"], cwd=cwd, env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, stdin=subprocess.DEVNULL, start_new_session=True)
    seen: list[str] = []
    deadline = time.monotonic() + rule.timeout
    try:
        assert proc.stdout is not None
        os.set_blocking(proc.stdout.fileno(), False)
        while time.monotonic() < deadline:
            line = proc.stdout.readline()
            if line:
                seen.append(line)
                if re.search(rule.ready, line):
                    return
            elif proc.poll() is not None:
                break
            else:
                time.sleep(0.2)
        pytest.fail(f"{where}: `{shell}` did not come up ({rule.why})\n{''.join(seen)[-3000:]}")
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGTERM)
            try:
                proc.wait(timeout=10)
            except subprocess.TimeoutExpired:
                os.killpg(proc.pid, signal.SIGKILL)


def check_install(command: str, where: str, venv: str | None = None) -> None:
    """An install command in the docs: every package it names is installed here (in ``venv`` for a block that runs
    in another venv), and every extra it names is one of pyproject.toml's (the tests do not reinstall anything)."""
    words = shlex.split(command)[2:]
    extras_declared = set(_pyproject()["project"]["optional-dependencies"])
    for word in words:
        if word.startswith("-") or word in (".", ):
            continue
        m = re.fullmatch(r"\.?\[([\w,]+)\]", word) or re.fullmatch(r"\S*billiards_env\[([\w,]+)\]", word)
        if m:
            missing = sorted(set(m.group(1).split(",")) - extras_declared)
            assert not missing, f"{where}: `{command}` names extras {missing} that pyproject.toml does not declare"
            continue
        name = re.split(r"[<>=\[ ]", word)[0]
        try:
            if venv and venv != ".venv":
                probe = subprocess.run([_python(venv), "-c", f"import importlib.metadata as m; m.version({name!r})"],
                                       capture_output=True, text=True, timeout=60)
                if probe.returncode != 0:
                    raise importlib.metadata.PackageNotFoundError(name)
            else:
                importlib.metadata.version(name)
        except importlib.metadata.PackageNotFoundError:
            pytest.fail(f"{where}: `{command}`: {name} is not installed in this venv, so the commands that follow "
                        f"it cannot be tested (pip install -e '.[zoo]' for the RL Zoo)")


def _pyproject() -> dict:
    import tomllib

    return tomllib.loads((ROOT / "pyproject.toml").read_text())


def _marks(block: Block) -> list:
    if block.skip:
        return [pytest.mark.skip(reason=f"{block.where}: {block.skip}")]
    slow = any((rule_for(prepare_name(c)) or Rule("", "")).slow for c in commands(block.code) + block.before)
    return [pytest.mark.slow] if slow else []


def prepare_name(command: str) -> str:
    for script, module in CONSOLE_SCRIPTS.items():
        command = re.sub(rf"^{re.escape(script)}\b", f"python -m {module}", command)
    return command


# --- the tests ----------------------------------------------------------------------------------------------
def test_every_block_says_its_language():
    """An unlabelled block could hide a command that never runs: each says python, bash, json, yaml or text."""
    bad = [f"{b.where} ({b.lang or 'no language'})" for b in BLOCKS if b.lang not in LANGS]
    assert not bad, f"label these blocks with one of {', '.join(LANGS)} ('text' if not meant to run): {bad}"


@pytest.mark.parametrize("block", DATA, ids=[b.where for b in DATA])
def test_data_block_parses(block: Block):
    if block.lang == "json":
        json.loads(block.code)
    else:
        yaml.safe_load(block.code)


OUTPUTS = [b for b in BLOCKS if b.output_of]


@pytest.mark.parametrize("block", OUTPUTS, ids=[b.where for b in OUTPUTS])
def test_output_sample_matches_the_command(block: Block, tmp_path: Path):
    """A sample of a command's output is what the command prints now (numbers to the digits the sample shows)."""
    assert block.lang == "json", f"{block.where}: output-of is checked on JSON blocks"
    box = make_sandbox(tmp_path)
    command, _ = prepare(block.output_of, box)
    proc = run_group(["bash", "-c", command.replace("python -m ", f"{shlex.quote(sys.executable)} -m ")],
                     DEFAULT_TIMEOUT, cwd=box, env=_env())
    assert proc.returncode == 0, proc.stderr[-2000:]
    shown, printed = json.loads(block.code, parse_float=_Shown), json.loads(proc.stdout)
    problems = _compare(shown, printed, "$")
    assert not problems, f"{block.where}: the sample differs from `{block.output_of}`: {problems[:10]}"


class _Shown(float):
    """A float parsed from a sample, remembering how many decimals it showed."""

    def __new__(cls, text: str) -> "_Shown":
        obj = super().__new__(cls, float(text))
        mantissa, _, exp = text.lower().partition("e")
        decimals = len(mantissa.partition(".")[2]) - (int(exp) if exp else 0)
        obj.tolerance = 0.5 * 10.0 ** (-decimals) * (1 + 1e-9)
        return obj


def _compare(shown: object, printed: object, at: str) -> list[str]:
    if isinstance(shown, dict):
        if not isinstance(printed, dict) or list(shown) != list(printed):
            return [f"{at}: keys {list(shown)} != {list(printed) if isinstance(printed, dict) else printed!r}"]
        return [p for k in shown for p in _compare(shown[k], printed[k], f"{at}.{k}")]
    if isinstance(shown, list):
        if not isinstance(printed, list) or len(shown) != len(printed):
            return [f"{at}: {len(shown)} items shown, {printed!r} printed"]
        return [p for k, (a, b) in enumerate(zip(shown, printed)) for p in _compare(a, b, f"{at}[{k}]")]
    if isinstance(shown, _Shown):
        ok = isinstance(printed, (int, float)) and abs(float(printed) - shown) <= shown.tolerance
        return [] if ok else [f"{at}: {float(shown)!r} shown, {printed!r} printed"]
    return [] if shown == printed and type(shown) is type(printed) else [f"{at}: {shown!r} shown, {printed!r} printed"]


@pytest.mark.parametrize("block", [pytest.param(b, marks=_marks(b), id=b.where) for b in SHELL])
def test_shell_block_runs(block: Block, tmp_path: Path):
    box = make_sandbox(tmp_path)
    cmds = block.before + commands(block.code)
    venvs = {rule.venv for rule in (rule_for(prepare_name(c)) for c in cmds) if rule is not None} - {".venv"}
    venv = min(venvs) if venvs else None  # a block naming a venv's commands runs wholly in it
    for command in cmds:
        run_command(command, box, block.where, venv)


def _python_files() -> list:
    """One test per file and venv: the file's python blocks for that venv, in order."""
    params = []
    for doc in DOCS:
        in_doc = [b for b in BLOCKS if b.path.as_posix() == doc and b.lang == "python"]
        for venv in sorted({b.venv for b in in_doc}):
            blocks = [b for b in in_doc if b.venv == venv]
            marks = [m for b in blocks for m in _marks(b) if m.name == "slow"][:1]
            params.append(pytest.param(doc, blocks, marks=marks, id=doc if venv == ".venv" else f"{doc}[{venv}]"))
    return params


RUNNER = r"""
import json, sys, time, traceback
blocks = json.load(open(sys.argv[1]))
scope = {"__name__": "__main__"}
for b in blocks:
    if b["skip"]:
        print(f"SKIPPED {b['where']}: {b['skip']}", flush=True)
        continue
    t0 = time.perf_counter()
    try:
        exec(compile(b["code"], b["where"], "exec"), scope)
    except BaseException:
        print(f"FAILED {b['where']}", flush=True)
        traceback.print_exc()
        sys.exit(1)
    print(f"PASSED {b['where']} ({time.perf_counter() - t0:.1f} s)", flush=True)
"""


@pytest.mark.parametrize("doc, blocks", _python_files())
def test_python_blocks_run(doc: str, blocks: list[Block], tmp_path: Path):
    """The python blocks of one file, in order, in one fresh process (a block may use an earlier one's names)."""
    box = make_sandbox(tmp_path)
    for b in blocks:
        if not b.skip:
            for command in b.before:
                run_command(command, box, b.where)
    spec = tmp_path / "blocks.json"
    spec.write_text(json.dumps([{"where": b.where, "code": b.code, "skip": b.skip} for b in blocks]))
    script = tmp_path / "run_blocks.py"
    script.write_text(RUNNER)
    env = _env()
    proc = run_group([_python(blocks[0].venv), str(script), str(spec)], PYTHON_TIMEOUT, cwd=box, env=env)
    ran = [line for line in proc.stdout.splitlines() if line.startswith(("PASSED", "FAILED", "SKIPPED"))]
    if proc.returncode != 0:
        pytest.fail(f"{doc}: {ran[-1] if ran else 'the blocks did not start'}\n--- stderr (end)\n"
                    f"{proc.stderr[-4000:]}")
    assert len(ran) == len(blocks), proc.stdout[-2000:]
    print("\n".join(ran))  # each block's time, shown with -s or on failure


# --- commands in the prose ----------------------------------------------------------------------------------
#: An inline command in the prose: `python -m MODULE ...`, a console script, or a venv's python running a module.
_INLINE = re.compile(r"`((?:\.venv[-\w]*/bin/)?python -m [\w.]+[^`]*|billiards-(?:sim|play)(?: [^`]*)?)`")


def inline_commands() -> dict[str, list[tuple[str, str]]]:
    """Commands quoted inline in the docs' prose (outside code blocks), by the module they run."""
    found: dict[str, list[tuple[str, str]]] = {}
    for doc in DOCS:
        text = re.sub(r"```.*?```", "", (ROOT / doc).read_text(encoding="utf-8"), flags=re.S)
        for m in _INLINE.finditer(" ".join(text.split())):
            command = prepare_name(re.sub(r"^\.venv[-\w]*/bin/", "", m.group(1)))
            module = command.split()[2]
            if "<" in module:
                continue
            found.setdefault(module, []).append((doc, command))
    return found


def test_inline_commands_name_real_modules_and_flags():
    """Each command quoted in the prose runs a module that exists, and every ``--flag`` it uses is one its
    ``--help`` lists (the flags of all modules checked in one go, their ``--help`` in parallel)."""
    import importlib.util

    found = inline_commands()
    assert "agents.train" in found and "billiards_env.sim" in found, sorted(found)
    for module in found:
        if module == "pip":
            continue
        top = module.split(".")[0]
        if top == "billiards_env" or (ROOT / top).is_dir():
            assert importlib.util.find_spec(module) is not None, f"{found[module][0]}: no module {module}"
    flagged = {m: cs for m, cs in found.items() if m != "pip" and any(" --" in c for _, c in cs)}
    procs = {}
    for module in sorted(flagged):
        venv = ".venv-rllib" if module in ("benchmarks.rllib_throughput",) else ".venv"
        exe = sys.executable if venv == ".venv" else str(ROOT / venv / "bin" / "python")
        if not Path(exe).exists():
            continue
        procs[module] = subprocess.Popen([exe, "-m", module, "--help"], cwd=ROOT, env=_env(), text=True,
                                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, stdin=subprocess.DEVNULL)
    problems = []
    for module, proc in procs.items():
        out, err = proc.communicate(timeout=300)
        if proc.returncode != 0:
            problems.append(f"`python -m {module} --help` failed: {err.strip().splitlines()[-1:]}")
            continue
        for doc, command in flagged[module]:
            for flag in re.findall(r"(?<![\w-])(--[a-z][\w-]*)", command):
                if flag not in out:
                    problems.append(f"{doc}: `{command}`: {flag} is not an option of python -m {module}")
    assert not problems, "\n".join(problems)
