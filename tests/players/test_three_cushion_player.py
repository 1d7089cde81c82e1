"""The three-cushion search player: it finds points, plays what it found, and is deterministic."""
from __future__ import annotations

import numpy as np
import pytest

from billiards_env.physics import Balls, Physics, Simulator
from billiards_env.games.carom_layout import CAROM_IDS, carom_balls
from billiards_env.physics.spin_collide import MAX_TIP_OFFSET
from billiards_env.physics.table import CAROM_BALL_MASS, CAROM_BALL_RADIUS, carom_table
from billiards_env.players.referee import three_cushion_turn
from billiards_env.players.three_cushion import (CaromSearchSettings, CaromShot, three_cushion_geometric_shot,
                                                three_cushion_shot)
from billiards_env.rules.three_cushion import ThreeCushion, summarize_carom

TABLE = carom_table()
SIM = Simulator(TABLE, Physics(friction="spin"))
#: A few layouts: the opening, and balls scattered (none frozen).
LAYOUTS = [
    None,
    {"white": (0.4, 0.3), "yellow": (2.2, 1.1), "red": (1.5, 0.6)},
    {"white": (2.5, 1.2), "yellow": (0.3, 1.2), "red": (0.5, 0.2)},
]


def balls_of(layout) -> Balls:
    if layout is None:
        return carom_balls(TABLE)
    return Balls.from_positions([layout[i] for i in CAROM_IDS], ids=CAROM_IDS, radius=CAROM_BALL_RADIUS,
                                mass=CAROM_BALL_MASS)


def scores(balls: Balls, shot, cue=0, opp=1, red=2) -> bool:
    res = SIM.run(balls.strike(cue, shot.angle, shot.speed, shot.side, shot.top))
    ev = np.stack([res.events.kind, res.events.ball, res.events.other], axis=1)
    return summarize_carom(ev, (cue, opp, red)).point


@pytest.mark.parametrize("layout", range(len(LAYOUTS)))
def test_search_finds_a_point_and_the_shot_scores(layout):
    balls = balls_of(LAYOUTS[layout])
    shot = three_cushion_shot(SIM, balls, 0, 1, 2)
    assert shot.point and scores(balls, shot)
    assert 0.0 < shot.robustness <= 1.0 and shot.cushions >= 3 and shot.simulated > 1000
    assert 0.5 <= shot.speed <= 6.0 and shot.side ** 2 + shot.top ** 2 <= MAX_TIP_OFFSET ** 2


def test_player_one_shoots_the_yellow():
    balls = balls_of(LAYOUTS[1])
    shot = three_cushion_shot(SIM, balls, 1, 0, 2)
    assert shot.point and scores(balls, shot, 1, 0, 2)
    state = ThreeCushion().initial_state(1)
    call, state = three_cushion_turn(SIM, balls.copy(), state, three_cushion_shot(SIM, balls, 1, 0, 2, opening=True))
    assert call.point and call.score == (0, 1) and state.shooter == 1


def test_search_is_deterministic_and_leaves_the_balls_alone():
    balls = balls_of(LAYOUTS[2])
    before = balls.pos.copy()
    a = three_cushion_shot(SIM, balls, 0, 1, 2)
    b = three_cushion_shot(SIM, balls, 0, 1, 2)
    assert a == b and np.array_equal(balls.pos, before)


def test_without_a_point_it_plays_the_nearest_miss():
    """A search too narrow to find a point reports so, and its shot indeed does not score."""
    balls = balls_of(LAYOUTS[1])
    narrow = CaromSearchSettings(sweep_angles=3, cut_aims=1, speeds=(1.0,), tips=((0.0, 0.0),), refine_rows=0)
    shot = three_cushion_shot(SIM, balls, 0, 1, 2, narrow)
    assert not shot.point and shot.robustness == 0.0 and shot.simulated == 5
    assert not scores(balls, shot)


def test_turn_applies_the_call_and_keeps_the_balls_where_they_stop():
    balls = balls_of(None)
    rules = ThreeCushion()
    state = rules.initial_state(0)
    shot = three_cushion_shot(SIM, balls, 0, 1, 2, opening=True)
    call, nxt = three_cushion_turn(SIM, balls, state, shot, rules)
    assert call.point == shot.point and (nxt.shooter == 0) == call.point and not call.foul
    assert call.first == "red"  # the opening shot meets the red first
    assert np.all(balls.vel == 0.0) and not np.array_equal(balls.pos, balls_of(None).pos)


@pytest.mark.parametrize("layout", [0, 2])
def test_geometric_player_scores_in_the_rolling_model(layout):
    """Without spin the straight-line model is the engine's: its shot scores (from these layouts)."""
    sim = Simulator(TABLE, Physics())
    balls = balls_of(LAYOUTS[layout])
    shot = three_cushion_geometric_shot(balls, TABLE, sim.physics, 0, 1, 2, red_first=layout == 0)
    assert shot.point and shot.cushions >= 3 and shot.side == shot.top == 0.0
    res = sim.run(balls.strike(0, shot.angle, shot.speed))
    s = summarize_carom(np.stack([res.events.kind, res.events.ball, res.events.other], axis=1), (0, 1, 2))
    assert s.point and (layout != 0 or (s.first == "red" and s.cushions_before_first == 0))


def test_geometric_player_rolls_the_cue_ball_under_the_spin_model():
    shot = three_cushion_geometric_shot(balls_of(LAYOUTS[1]), TABLE, SIM.physics, 0, 1, 2)
    assert shot.top == 0.4 and shot.side == 0.0 and 0.5 <= shot.speed <= 6.0


def test_the_referee_plays_the_squirt_of_the_physics():
    """Under a physics with squirt (the pooltool preset), the referee's turn is the shot the physics plays: side
    english turns the cue ball's path (``Balls.strike(physics=...)``), not the unturned strike."""
    sim = Simulator(TABLE, Physics.from_preset("pooltool"))
    balls = balls_of(LAYOUTS[1])
    shot = CaromShot(angle=0.3, speed=2.0, side=0.3, top=0.1, point=False, robustness=0.0, cushions=0,
                     simulated=0)
    played = balls.copy()
    three_cushion_turn(sim, played, ThreeCushion().initial_state(0), shot)
    squirted = sim.run(balls.strike(0, shot.angle, shot.speed, shot.side, shot.top, physics=sim.physics))
    unturned = sim.run(balls.strike(0, shot.angle, shot.speed, shot.side, shot.top))
    assert np.array_equal(played.pos, squirted.balls.pos)
    assert not np.allclose(played.pos, unturned.balls.pos, atol=1e-3)


def test_geometric_player_under_spin_plays_an_aim_the_engine_scores():
    """Under the spin model the straight lines are a guess: given the simulator, the geometric player has the
    engine play its scoring aims and chooses one that scores, on most random positions (without it: hardly any)."""
    from billiards_env.physics.layout import place_random

    rng = np.random.default_rng(7)
    checked = unchecked = 0
    n = 12
    r = CAROM_BALL_RADIUS
    for _ in range(n):
        pos = np.zeros((3, 2))
        place_random(rng, pos, [0, 1, 2], [(r, TABLE.length - 2 * r, r, TABLE.width - 2 * r)] * 3, [], [], 0.0,
                     2 * r + 1e-3)
        balls = Balls.from_positions(pos, ids=CAROM_IDS, radius=r, mass=CAROM_BALL_MASS)
        shot = three_cushion_geometric_shot(balls, TABLE, SIM.physics, 0, 1, 2, sim=SIM)
        assert shot.top == 0.4 and shot.side == 0.0 and shot.simulated <= 40
        if shot.point:
            assert scores(balls, shot)  # what it says scores, scores
        checked += scores(balls, shot)
        unchecked += scores(balls, three_cushion_geometric_shot(balls, TABLE, SIM.physics, 0, 1, 2))
    assert checked >= n // 2 and checked > unchecked
