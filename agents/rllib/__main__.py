"""``python -m agents.rllib``: see :mod:`agents.rllib.train`."""
import sys

from .train import main

sys.exit(main())
