"""Which model file of a training run to load: :func:`model_file` (the README's "trained model in three lines").

``agents.train`` writes ``final_model.zip`` at the end of every run and ``best_model.zip`` only once an evaluation
has run (``eval_freq`` steps): a run stopped sooner has no best model. Loading picks the best if the run has one,
else the final one, and says which.
"""
from __future__ import annotations

import sys
from pathlib import Path

#: The model files of a run folder, in the order they are preferred.
MODEL_FILES = ("best_model.zip", "final_model.zip")


def model_file(run: str | Path, quiet: bool = False) -> Path:
    """The model zip of run folder ``run``: ``best_model.zip`` (the best evaluation's) if it exists, else
    ``final_model.zip`` (the model at the end of the run); prints which on stderr unless ``quiet``. A
    :class:`FileNotFoundError` names the folder and what it holds when it has neither."""
    folder = Path(run)
    if not folder.is_dir():
        raise FileNotFoundError(f"{folder}: no such run folder (give the folder agents.train made, runs/<name>-<time>)")
    for name in MODEL_FILES:
        path = folder / name
        if path.is_file():
            if not quiet:
                why = "the best evaluation's" if name == MODEL_FILES[0] else \
                    "the model at the end of the run; it has no best_model.zip: it ended before its first evaluation"
                print(f"loading {path} ({why})", file=sys.stderr)
            return path
    held = ", ".join(sorted(p.name for p in folder.iterdir())) or "nothing"
    raise FileNotFoundError(f"{folder}: no {' or '.join(MODEL_FILES)} (it holds {held}); is the run still training, "
                            "or did it stop before saving?")


__all__ = ["MODEL_FILES", "model_file"]
