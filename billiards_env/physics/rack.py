"""Racks moved to :mod:`.layout` (the one module for spots, racks and placements); kept as an import path."""
from .layout import RACK_ORDER, rack_balls, triangle_positions  # noqa: F401
