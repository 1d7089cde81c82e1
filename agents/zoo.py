"""RL Baselines3 Zoo run folders, read without the zoo and without YAML's unsafe loader.

``python -m rl_zoo3.train ... -f logs`` writes ``logs/<algo>/<env_id>_<k>/``: the final model ``<env_id>.zip``,
``best_model.zip`` (its evaluations' best), and ``<env_id>/config.yml`` + ``args.yml`` (the hyperparameters and the
command line, env kwargs included, dumped as ``OrderedDict`` objects that only ``yaml.UnsafeLoader`` reads). This
module reads them with a safe loader that knows that one tag, so a zoo-trained model plays like any other::

    python -m agents.zoo logs/sac/BilliardsOneBall-v0_1     # writes env.json there: the README's three lines load it
    python -m agents.evaluate --players logs/sac/BilliardsOneBall-v0_1 geometric --episodes 1000
"""
from __future__ import annotations

import argparse
import json
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Sequence

import yaml

from .config import ALGOS

_ORDERED_DICT = "tag:yaml.org,2002:python/object/apply:collections.OrderedDict"


class _ZooLoader(yaml.SafeLoader):
    """A safe loader that reads the zoo's ``!!python/object/apply:collections.OrderedDict`` as a plain dict (a list
    of key-value pairs); every other Python tag stays refused."""


def _ordered_dict(loader: yaml.SafeLoader, node: yaml.Node) -> dict[str, Any]:
    pairs = loader.construct_sequence(node, deep=True)
    if len(pairs) == 1 and isinstance(pairs[0], list) and all(isinstance(p, list) and len(p) == 2 for p in pairs[0]):
        pairs = pairs[0]
    return {str(k): v for k, v in pairs}


_ZooLoader.add_constructor(_ORDERED_DICT, _ordered_dict)


def read_yaml(path: Path) -> dict[str, Any]:
    """A zoo YAML file (config.yml, args.yml) as a dict."""
    data = yaml.load(Path(path).read_text(), Loader=_ZooLoader)  # noqa: S506 - a SafeLoader subclass
    return dict(data or {})


@dataclass(frozen=True)
class ZooRun:
    """What a zoo run folder trained: the env id and kwargs, the algorithm and the model to load."""

    run_dir: Path
    env_id: str
    algo: str
    env_kwargs: dict[str, Any]
    model_zip: Path
    vecnormalize: Path | None


def _params_dir(run_dir: Path) -> Path | None:
    for sub in sorted(run_dir.iterdir()) if run_dir.is_dir() else []:
        if sub.is_dir() and (sub / "config.yml").exists():
            return sub
    return None


def is_zoo_run(path: str | Path) -> bool:
    """True for a zoo run folder (a folder holding ``<env_id>/config.yml``) or a model ``.zip`` directly in one."""
    p = Path(path)
    run_dir = p.parent if p.suffix == ".zip" else p
    return _params_dir(run_dir) is not None and not (run_dir / "config.yaml").exists()


def read_zoo_run(path: str | Path) -> ZooRun:
    """The zoo run at ``path`` (its folder, or a model ``.zip`` in it: default ``best_model.zip`` if it exists,
    else the final ``<env_id>.zip``)."""
    p = Path(path)
    run_dir = p.parent if p.suffix == ".zip" else p
    params = _params_dir(run_dir)
    if params is None:
        raise ValueError(f"{path}: not an RL Zoo run folder (expected <env_id>/config.yml inside)")
    env_id = params.name
    config = read_yaml(params / "config.yml")
    args = read_yaml(params / "args.yml") if (params / "args.yml").exists() else {}
    env_kwargs = dict(config.get("env_kwargs") or args.get("env_kwargs") or {})
    algo = str(args.get("algo") or run_dir.parent.name).lower()
    if algo not in ALGOS:
        raise ValueError(f"{run_dir}: algorithm {algo!r} is not one of {', '.join(ALGOS)}")
    if p.suffix == ".zip":
        model = p
    else:
        model = run_dir / "best_model.zip" if (run_dir / "best_model.zip").exists() else run_dir / f"{env_id}.zip"
    if not model.exists():
        raise ValueError(f"{run_dir}: no model ({model.name}); has the zoo finished training?")
    vn = params / "vecnormalize.pkl"
    return ZooRun(run_dir, env_id, algo, env_kwargs, model, vn if vn.exists() else None)


def write_env_json(path: str | Path) -> Path:
    """Write ``env.json`` (``{"id": ..., "kwargs": ...}``, as ``agents.train`` does) into the zoo run folder, so
    the README's three lines load its ``best_model.zip``; returns the file."""
    run = read_zoo_run(path)
    out = run.run_dir / "env.json"
    out.write_text(json.dumps({"id": run.env_id, "kwargs": run.env_kwargs}, indent=2))
    return out


def main(argv: Sequence[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m agents.zoo",
                                description="Read an RL Zoo run folder and write its env.json (the env id and kwargs "
                                            "the model was trained on), as agents.train's run folders have.")
    p.add_argument("runs", nargs="+", help="zoo run folders, e.g. logs/sac/BilliardsOneBall-v0_1")
    args = p.parse_args(argv)
    try:
        for path in args.runs:
            run = read_zoo_run(path)
            out = write_env_json(path)
            print(f"{run.run_dir}: {run.algo.upper()} on {run.env_id} {run.env_kwargs}, model {run.model_zip.name}; "
                  f"wrote {out}")
    except (ValueError, OSError, yaml.YAMLError) as exc:
        print(f"agents.zoo: error: {exc}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
