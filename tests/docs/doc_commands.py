"""How the docs' shell commands run in the tests: budgets, venvs, placeholders (tests/docs/test_doc_blocks.py).

Every command of a bash block runs. A command that matches a rule below runs as the rule says: with short budgets
appended or substituted (``--seconds 300`` becomes a few seconds, ``--episodes 1000`` a handful, ``--shots
100000`` a few hundred), as a slow test, in the RLlib venv, as a server that must come up, or as an install
command that is checked rather than run. Any other command runs as written, in the default set, and must finish
within ``DEFAULT_TIMEOUT`` seconds: a new long command fails there until it gets a rule (that is the point: a
README command that crashes or hangs fails CI).

Commands run in a sandbox: a temporary folder holding copies of ``agents/`` and ``benchmarks/`` (so run folders
and reports land in the sandbox, not in the checkout) and links to the rest of the repository; the package
imports from the checkout. The placeholder ``runs/<run>`` is the newest run folder made in the sandbox.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

#: Seconds a command without a rule may take.
DEFAULT_TIMEOUT = 90.0

#: The package's console scripts (pyproject [project.scripts]) and the module each runs, so the docs' commands
#: run the checkout's code even where the installed scripts point elsewhere.
CONSOLE_SCRIPTS = {"billiards-sim": "billiards_env.sim", "billiards-play": "billiards_env.play"}

#: A tiny training run (a few seconds, an evaluation, a checkpoint), for the commands that train with agents.train.
TINY_TRAIN = "--seconds 4 --set eval_freq=400 n_eval_episodes=10 n_eval_envs=5 checkpoint_seconds=0 --no-progress"


@dataclass
class Rule:
    """How commands matching ``pattern`` (a regex, at the start of the command) run in the tests."""

    pattern: str
    why: str  #: what the rule is for (shown when it fails)
    sub: list[tuple[str, Any]] = field(default_factory=list)  #: regex substitutions (a string or a function)
    add: str = ""  #: arguments appended
    add_missing: dict[str, str] = field(default_factory=dict)  #: flag -> value, appended if the flag is absent
    slow: bool = False
    timeout: float = DEFAULT_TIMEOUT
    kind: str = "run"  #: run | server (must come up, then stopped) | pip (checked, not run)
    venv: str = ".venv"  #: the venv whose python runs it (".venv-rllib": RLlib, ".venv-clients": the RL Zoo and
    #: the other client libraries; skipped where absent)
    cwd: str = "sandbox"  #: sandbox, or root (the checkout: scripts that cd there themselves)
    expect: int = 0  #: exit status expected
    ready: str = ""  #: server: a regex its output matches once it is up

    def matches(self, command: str) -> bool:
        return re.match(self.pattern, command) is not None

    def apply(self, command: str) -> str:
        for old, new in self.sub:
            command = re.sub(old, new, command)
        missing = " ".join(f"{flag} {value}" for flag, value in self.add_missing.items()
                           if not re.search(rf"(^| ){re.escape(flag)}( |=|$)", command))
        return " ".join(part for part in (command, missing, self.add) if part)


RULES: list[Rule] = [
    Rule(r"bash scripts/test\.sh", "the test suite itself: collect it (setting up as CI does) instead of running it",
         add="--collect-only -q -p no:cacheprovider", slow=True, timeout=900, cwd="root"),
    Rule(r"bash scripts/main\.sh", "the main job (13 min of training): the same module with a tiny budget",
         sub=[(r"^bash scripts/main\.sh", "python -m agents.main")],
         add="--seconds 4 --episodes 10 --baselines geometric random --gif-episodes 1 --out runs/main "
             "--no-progress", slow=True, timeout=600),
    Rule(r"bash scripts/setup\.sh", "the set-up: idempotent where the venv is made (CI); quick then",
         slow=True, timeout=900, cwd="root"),
    Rule(r"\.venv-docs/bin/mkdocs build", "the docs site (scripts/test.sh builds it too): strictly, into a temporary "
         "folder, in .venv-docs", add='--site-dir "$(mktemp -d)"', venv=".venv-docs", slow=True, timeout=300,
         cwd="root"),
    Rule(r"python -m (ruff|mypy)\b", "the linters (scripts/test.sh runs them too): on the checkout, whose "
         "pyproject.toml configures them and whose billiards_env/ they read (the sandbox links neither)",
         timeout=300, cwd="root"),
    Rule(r"pip install", "install commands: every package they name is installed (or is an extra of "
                         "pyproject.toml), not reinstalled", kind="pip"),
    Rule(r"python -m agents\.train --resume", "resume with a total budget above what the tiny run spent (a total "
                                               "given is scaled by 1/100: 1080 s become 10.8)",
         sub=[(r"--seconds (\S+)", lambda m: f"--seconds {float(m.group(1)) / 100:g}")],
         add_missing={"--seconds": "8"}, add="--no-progress", slow=True, timeout=300),
    Rule(r"python -m agents\.train", "training: a few seconds (in the default set: the README's three lines "
                                      "load the run it makes)",
         sub=[(r"--seconds \S+", "")], add=TINY_TRAIN, timeout=300),
    Rule(r"python -m agents\.evaluate", "evaluation: a few episodes",
         sub=[(r"--episodes \S+", "--episodes 5")], add="--gif-episodes 1", slow=True, timeout=600),
    Rule(r"python -m agents\.main", "the main job: a tiny budget",
         add="--seconds 4 --episodes 10 --baselines geometric random --gif-episodes 1 --no-progress", slow=True,
         timeout=600),
    Rule(r"python -m agents\.dataset", "a dataset as written (2000 expert episodes, numba compiles included: a "
                                        "minute or two on a busy machine)", timeout=300),
    Rule(r"python -m agents\.league", "a league: two games a pair",
         sub=[(r"--games \S+", "--games 2"), (r"--runouts \S+", "--runouts 2")], slow=True, timeout=600),
    Rule(r"python -m agents\.rllib", "RLlib training: two iterations, in the RLlib venv",
         add="--iterations 2 --eval-every 1 --eval-episodes 5 --num-env-runners 0", venv=".venv-rllib", slow=True,
         timeout=900),
    Rule(r"python -m rl_zoo3\.train", "RL Zoo training: a few thousand steps, with evaluations (clients venv)",
         add="-n 2000 --eval-freq 1000 --eval-episodes 5 --save-freq -1", slow=True, timeout=600,
         venv=".venv-clients"),
    Rule(r"python -m rl_zoo3\.enjoy", "RL Zoo playback: a few steps, in the clients venv", add="-n 50", slow=True,
         timeout=300, venv=".venv-clients"),
    Rule(r"python -m billiards_env\.fuzz --shots", "fuzzing: a few hundred shots",
         sub=[(r"--shots \S+", "--shots 60"), (r"--workers \S+", "--workers 1"), (r"--out \S+", "--out fuzz-out")],
         timeout=300),
    Rule(r"python -m benchmarks\.new_games", "the new games' players: a few positions and one frame",
         sub=[(r"--three-cushion \S+", "--three-cushion 4"), (r"--frames \S+", "--frames 1")], slow=True,
         timeout=600),
    Rule(r"python -m benchmarks", "benchmarks: the quick run of one section",
         add="--quick", slow=True, timeout=900),
    Rule(r"tensorboard ", "TensorBoard: a server; it must come up", add="--port 0", kind="server",
         ready=r"TensorBoard \S+ at http", slow=True, timeout=120),
]


def rule_for(command: str) -> Rule | None:
    """The first rule whose pattern matches ``command``, or None (run as written, default budget)."""
    for rule in RULES:
        if rule.matches(command):
            return rule
    return None


__all__ = ["Rule", "RULES", "rule_for", "DEFAULT_TIMEOUT", "CONSOLE_SCRIPTS", "TINY_TRAIN"]
