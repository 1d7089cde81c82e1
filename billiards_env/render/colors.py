"""Colours of the table and of the balls (RGB 0-255 tuples).

Ball numbers 0-15 follow the usual American pool set: 0 is the cue ball, 1-7 solids, 8 the black, 9-15 stripes
that repeat the colours of 1-7 on a white ball. Numbers 16-25 are plain balls without a number: snooker's red
(16) and colours (17 yellow .. 22 black, in the order of their values), and the carom set (23 white, 24 yellow,
25 red).
"""
from __future__ import annotations

RGB = tuple[int, int, int]

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
#: Plain balls (no number, no stripe) by drawing number: snooker's, then carom's.
PLAIN_BALLS: dict[int, RGB] = {
    16: (196, 22, 28),  # snooker red
    17: (250, 204, 20),  # yellow
    18: (0, 120, 64),  # green
    19: (120, 70, 30),  # brown
    20: (22, 70, 180),  # blue
    21: (244, 140, 170),  # pink
    22: (18, 18, 20),  # black
    23: (248, 246, 238),  # carom white
    24: (250, 214, 40),  # carom yellow
    25: (204, 26, 30),  # carom red
}
MAX_DRAW_NUMBER = max(PLAIN_BALLS)

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


def is_stripe(number: int) -> bool:
    """True for the striped balls 9-15."""
    _check_number(number)
    return 9 <= int(number) <= MAX_BALL_NUMBER


def is_numbered(number: int) -> bool:
    """True for the numbered pool balls 1-15 (they carry a number disc)."""
    _check_number(number)
    return 1 <= int(number) <= MAX_BALL_NUMBER


def ball_colour(number: int) -> RGB:
    """Main colour of ball ``number`` (0 = cue ball; for stripes 9-15 the colour of the stripe band; 16-25 the plain
    balls of snooker and carom)."""
    _check_number(number)
    n = int(number)
    if n in PLAIN_BALLS:
        return PLAIN_BALLS[n]
    return _SOLIDS[n - 8] if n > 8 else _SOLIDS[n]


def _check_number(number: int) -> None:
    """Reject numbers outside the drawn sets with a message that says what is allowed."""
    if isinstance(number, bool) or int(number) != number or not 0 <= int(number) <= MAX_DRAW_NUMBER:
        raise ValueError(f"ball number must be an integer 0-{MAX_DRAW_NUMBER} (0 = cue ball, 1-15 the pool balls, "
                         f"16-25 the plain balls of snooker and carom), got {number!r}")
