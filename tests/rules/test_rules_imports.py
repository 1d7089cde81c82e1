"""The rules layer stands alone: no Gymnasium, no pygame (like the physics)."""
from __future__ import annotations

import ast
import pathlib
import subprocess
import sys

import billiards_env.rules

RULES_DIR = pathlib.Path(billiards_env.rules.__file__).parent


def test_rules_sources_import_neither_gymnasium_nor_pygame():
    files = sorted(RULES_DIR.glob("*.py"))
    assert len(files) >= 5
    for path in files:
        for node in ast.walk(ast.parse(path.read_text())):
            names = []
            if isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                names = [node.module or ""]
            for name in names:
                top = name.split(".")[0]
                assert top not in ("gymnasium", "gym", "pygame"), f"{path.name} imports {name}"
                if node.__class__ is ast.ImportFrom and node.level > 0:
                    assert not name.startswith(("envs", "render")), f"{path.name} imports .{name}"


def test_importing_the_rules_does_not_load_pygame():
    code = "import sys, billiards_env.rules; print('pygame' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"
