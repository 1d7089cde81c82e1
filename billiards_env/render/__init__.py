"""billiards_env.render: draws a given table state (no physics, no Gymnasium).

``TableRenderer`` paints frames off-screen (no display needed), ``HumanWindow`` shows them on screen,
``write_gif`` / ``write_png`` save them, and ``frame_times`` picks the instants of a shot to draw. Under the spin
model the balls turn with their spins (:mod:`.animation` integrates them, :mod:`.sprites` draws turned balls) and
a cue-ball diagram shows the tip offset (:mod:`.overlays`); games add a panel (:mod:`.hud`) from plain data.
"""
from . import colors
from .animation import frame_times
from .colors import ball_colour, is_stripe
from .gif import write_gif, write_png
from .table_renderer import TableRenderer
from .window import HumanWindow

__all__ = [
    "colors", "frame_times", "ball_colour", "is_stripe", "write_gif", "write_png", "TableRenderer", "HumanWindow",
]
