"""The layers hold: imports flow one way, and nothing imports in a circle.

Read from the sources (AST): every module-level import between the project's modules (``billiards_env``,
``agents``, ``benchmarks``), function-level imports included except those under ``if TYPE_CHECKING`` and the lazy
imports of pygame-backed drawing (``billiards_env.render``), which the env loads only when something is drawn."""
from __future__ import annotations

import ast
import functools
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("billiards_env", "agents", "benchmarks")
#: Which layer of the package each module belongs to, and the layers it may import (besides itself).
LAYERS = {
    "physics": set(),
    "rules": {"physics"},
    "games": {"physics", "rules", "table_state", "shot_path"},
    "table_state": {"physics"},
    "shot_path": {"physics", "table_state"},
    "players": {"physics", "rules", "games", "table_state", "shot_path"},
    "envs": {"physics", "rules", "games", "table_state", "shot_path", "players", "render", "registration",
             "machine"},
    "multi": {"envs", "players", "rules", "games", "table_state", "physics", "registration", "render"},
    "render": {"physics"},
}
#: Layers that must not import Gymnasium or pygame.
NO_GYM = ("physics", "rules", "games", "table_state", "shot_path", "players")


def _module_name(path: Path) -> str:
    rel = path.relative_to(ROOT).with_suffix("")
    parts = list(rel.parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def _is_type_checking(node: ast.If) -> bool:
    """``if TYPE_CHECKING:`` (imports for annotations only) or ``if __name__ == "__main__":`` (run as a script)."""
    t = node.test
    if isinstance(t, ast.Compare) and isinstance(t.left, ast.Name) and t.left.id == "__name__":
        return True
    return (isinstance(t, ast.Name) and t.id == "TYPE_CHECKING") or \
        (isinstance(t, ast.Attribute) and t.attr == "TYPE_CHECKING")


@functools.lru_cache(maxsize=None)
def _imports(path: Path) -> list[tuple[str, bool]]:
    """``(imported module, at module level)`` for every import of ``path`` outside ``TYPE_CHECKING`` blocks."""
    tree = ast.parse(path.read_text())
    module = _module_name(path)
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    out: list[tuple[str, bool]] = []

    def visit(node: ast.AST, top: bool) -> None:
        for child in ast.iter_child_nodes(node):
            if isinstance(child, ast.If) and _is_type_checking(child):
                continue
            if isinstance(child, ast.Import):
                out.extend((a.name, top) for a in child.names)
            elif isinstance(child, ast.ImportFrom):
                if child.level:
                    base = package.split(".")
                    base = base[:len(base) - (child.level - 1)]
                    name = ".".join(base + ([child.module] if child.module else []))
                else:
                    name = child.module or ""
                out.append((name, top))
                for a in child.names:  # "from pkg import module"
                    out.append((f"{name}.{a.name}", top))
            visit(child, top and not isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)))

    visit(tree, True)
    return out


def _project_modules() -> dict[str, Path]:
    mods = {}
    for pkg in PACKAGES:
        for path in sorted((ROOT / pkg).rglob("*.py")):
            mods[_module_name(path)] = path
    return mods


MODULES = _project_modules()


def _resolve(name: str) -> str | None:
    while name and name not in MODULES:
        name = name.rpartition(".")[0]
    return name or None


@functools.lru_cache(maxsize=None)
def _graph(include_lazy: bool) -> dict[str, set[str]]:
    graph: dict[str, set[str]] = {m: set() for m in MODULES}
    for mod, path in MODULES.items():
        for name, top in _imports(path):
            if not (top or include_lazy):
                continue
            if not top and name.startswith(("billiards_env.render", "billiards_env.envs.recording")):
                continue  # drawing loads pygame only when something is drawn
            target = _resolve(name)
            if target and target != mod and not mod.startswith(target + "."):  # a package's own __init__ is fine
                graph[mod].add(target)
    return graph


def _layer(module: str) -> str | None:
    parts = module.split(".")
    return parts[1] if parts[0] == "billiards_env" and len(parts) > 1 else None


def _cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """Every strongly connected component with more than one module (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on: set[str] = set()
    out: list[list[str]] = []
    counter = [0]

    def strong(v: str) -> None:
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                strong(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            strong(v)
    return out


def test_the_project_has_modules_to_check():
    assert {"billiards_env.envs.base", "billiards_env.table_state", "agents.evaluate", "benchmarks.common"} <= \
        set(MODULES)


def test_no_import_circles_including_function_level_imports():
    assert _cycles(_graph(include_lazy=True)) == []


def test_a_planted_circle_is_found():
    assert _cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]


@pytest.mark.parametrize("layer", sorted(LAYERS))
def test_layers_import_only_the_layers_below(layer):
    graph = _graph(include_lazy=True)
    bad = []
    for mod, targets in graph.items():
        if _layer(mod) != layer:
            continue
        for t in targets:
            tl = _layer(t)
            if t.startswith(("agents", "benchmarks", "tests")):
                bad.append((mod, t))
            elif tl is not None and tl != layer and tl not in LAYERS[layer]:
                bad.append((mod, t))
    assert bad == []


@pytest.mark.parametrize("layer", NO_GYM)
def test_lower_layers_import_neither_gymnasium_nor_pygame(layer):
    bad = []
    for mod, path in MODULES.items():
        if _layer(mod) != layer:
            continue
        for name, _ in _imports(path):
            if name.split(".")[0] in ("gymnasium", "gym", "pygame"):
                bad.append((mod, name))
    assert bad == []


def test_agents_do_not_import_the_benchmarks():
    """The agents' reports share the machine report through :mod:`billiards_env.machine`; a benchmark may measure
    the agents' code (``benchmarks.rllib_throughput``), never the reverse."""
    graph = _graph(include_lazy=True)
    bad = [(m, t) for m, ts in graph.items() for t in ts if m.startswith("agents") and t.startswith("benchmarks")]
    assert bad == []


#: Attributes with a leading underscore that are public API (namedtuple's).
_NAMEDTUPLE_API = ("_replace", "_asdict", "_fields", "_make")


def _private_reaches(path: Path) -> list[str]:
    """``line: x._name`` for every read of a private attribute of an object other than ``self``/``cls``/``super()``
    in ``path`` (another object's private fields: a reach across modules)."""
    out = []
    for node in ast.walk(ast.parse(path.read_text())):
        if not (isinstance(node, ast.Attribute) and node.attr.startswith("_") and not node.attr.startswith("__")):
            continue
        base = node.value
        if isinstance(base, ast.Name) and base.id in ("self", "cls") or node.attr in _NAMEDTUPLE_API:
            continue
        if isinstance(base, ast.Call) and isinstance(base.func, ast.Name) and base.func.id == "super":
            continue
        out.append(f"{node.lineno}: {ast.unparse(node)}")
    return out


def test_no_module_reads_other_objects_private_attributes():
    """Parts use each other's public properties and methods (the native vector env's tables, the rules' states), in
    the package, the agents and the benchmarks alike (the solver profile times the solver's public stages; the
    distillation reads SB3's policy through its public modules)."""
    bad = {mod: r for mod, path in MODULES.items() if (r := _private_reaches(path))}
    assert bad == {}


def test_a_planted_private_reach_is_found(tmp_path):
    path = tmp_path / "m.py"
    path.write_text("def f(env, x):\n    a = self._ok\n    b = x._replace(a=1)\n    return env._hidden\n")
    assert _private_reaches(path) == ["4: env._hidden"]
