"""Colours of the table and of the balls (RGB 0-255 tuples).

Ball numbers 0-15 follow the usual American pool set: 0 is the cue ball, 1-7 solids, 8 the black, 9-15 stripes
that repeat the colours of 1-7 on a white ball. A game's other balls are plain balls without a number, drawn
in the colours of its ``palette`` (drawing number -> colour, numbers above 15; a game's session declares it:
snooker's reds and colours, the carom set), which the env hands to the renderer.
"""
from __future__ import annotations

from typing import Mapping

RGB = tuple[int, int, int]
#: A game's plain balls: drawing number (> 15) -> colour.
Palette = Mapping[int, RGB]

# --- balls -------------------------------------------------------------------------------------------------
CUE_BALL: RGB = (246, 242, 226)  #: the cue ball: ivory white
STRIPE_WHITE: RGB = (248, 246, 238)  #: the white body of the stripes 9-15
NUMBER_DISC: RGB = (252, 251, 246)  #: the small white circle that carries the number
NUMBER_INK: RGB = (12, 12, 12)  #: the printed number

#: Main colour of balls 1..8 (index = number); stripes 9..15 use the colour of ``number - 8``.
_SOLIDS: tuple[RGB, ...] = (
    CUE_BALL,
    (250, 196, 0),  # 1 yellow
    (18, 58, 170),  # 2 blue
    (204, 26, 30),  # 3 red
    (88, 38, 138),  # 4 purple
    (244, 104, 12),  # 5 orange
    (0, 118, 62),  # 6 green
    (124, 22, 32),  # 7 maroon
    (16, 16, 18),  # 8 black
)
MAX_BALL_NUMBER = 15  #: the numbered pool balls are 1..15

# --- table -------------------------------------------------------------------------------------------------
CLOTH: RGB = (26, 122, 66)  #: playing surface (the nominal colour; the renderer adds a soft light falloff)
CUSHION: RGB = (16, 92, 48)  #: cushion rubber covered in cloth: a darker green
RAIL: RGB = (112, 62, 30)  #: wooden rail
RAIL_DARK: RGB = (70, 36, 16)  #: rail edges and grain
POCKET: RGB = (0, 0, 0)  #: pocket openings
POCKET_LINER: RGB = (28, 24, 22)  #: leather around a pocket's throat
DIAMOND: RGB = (232, 226, 206)  #: mother-of-pearl sights on the rails
TRAY: RGB = (34, 24, 18)  #: strip below the table that holds pocketed balls
BACKGROUND: RGB = (22, 22, 24)  #: around the table
AIM_LINE: RGB = (236, 240, 232)  #: the aim line from the cue ball (drawn semi-transparent)
MARKING: RGB = (210, 226, 214)  #: chalk lines on the cloth (snooker's baulk line and D)


def is_stripe(number: int, palette: Palette | None = None) -> bool:
    """True for the striped balls 9-15 (``palette``: the game's plain balls, which are not)."""
    _check_number(number, palette)
    return 9 <= int(number) <= MAX_BALL_NUMBER


def is_numbered(number: int, palette: Palette | None = None) -> bool:
    """True for the numbered pool balls 1-15 (they carry a number disc)."""
    _check_number(number, palette)
    return 1 <= int(number) <= MAX_BALL_NUMBER


def ball_colour(number: int, palette: Palette | None = None) -> RGB:
    """Main colour of ball ``number`` (0 = cue ball; for stripes 9-15 the colour of the stripe band; a number of
    ``palette``, the game's plain balls: its colour there)."""
    _check_number(number, palette)
    n = int(number)
    if n > MAX_BALL_NUMBER:
        r, g, b = palette[n]  # type: ignore[index]
        return int(r), int(g), int(b)
    return _SOLIDS[n - 8] if n > 8 else _SOLIDS[n]


def check_palette(palette: Palette | None) -> dict[int, RGB]:
    """``palette`` as a dict (empty for None), or a ValueError saying what a palette holds."""
    out: dict[int, RGB] = {}
    for number, rgb in (palette or {}).items():
        ok = not isinstance(number, bool) and isinstance(number, int) and number > MAX_BALL_NUMBER
        try:
            colour = tuple(int(c) for c in rgb)
        except (TypeError, ValueError):
            colour = ()
        if not ok or len(colour) != 3 or not all(0 <= c <= 255 for c in colour):
            raise ValueError(f"palette: expected drawing numbers > {MAX_BALL_NUMBER} mapped to (r, g, b) colours "
                             f"0-255, got {number!r}: {rgb!r}")
        out[number] = colour  # type: ignore[assignment]
    return out


def _check_number(number: int, palette: Palette | None = None) -> None:
    """Reject numbers outside the drawn sets with a message that says what is allowed."""
    if isinstance(number, bool) or int(number) != number or not (
            0 <= int(number) <= MAX_BALL_NUMBER or (palette is not None and int(number) in palette)):
        extra = f", or the game's plain balls {sorted(palette)}" if palette else ""
        raise ValueError(f"ball number must be an integer 0-{MAX_BALL_NUMBER} (0 = cue ball, 1-15 the pool balls"
                         f"{extra}; a game's other balls need its palette), got {number!r}")
