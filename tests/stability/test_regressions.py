"""Regression tests for engine violations found by the fuzz (``python -m billiards_env.fuzz``), each reduced to a
minimal scene file in ``cases/`` (run one with ``billiards-sim cases/NAME.json --events`` or
``python -m billiards_env.fuzz --check cases/NAME.json``). All of them failed on the engine of 5a05464; the
sticky-contact merge, same-instant floor and cluster jam of 045a197 fixed them, and these tests keep it so.

1. Missed re-contact of a sliding pair (exact solver, rolling friction). Two touching balls whose relative
   velocity along the line of centres is zero or a tiny opening speed (after a micro-collision, or after a
   cushion hit removed a component) but which decelerate along different directions, so the gap closes
   (gap(t) = c0 + c1 t + c2 t^2 + ... with c0 ~ 0 up to rounding, 0 <= c1 < closing_tol, c2 < 0).
   ``roots.first_entry`` only reports an entry into contact from a positive gap; here the gap is never positive by
   more than rounding, so no collision is predicted, the balls move through each other until one of them has its
   next own event (a stop), and the overlap found then (0.1 - 1.2 mm) is resolved as an ordinary collision. The
   inelastic-collapse guard does not help: it separates at ``min(v_close, speed_floor)``, which for a nearly
   zero ``v_close`` is nearly zero, and it is off for ``e = 1``.
2. Inelastic-collapse storms (exact solver): with ball restitution 0 (or small) under the drag law (where the guard
   is off) a cluster of touching balls is resolved as tens of thousands of pairwise collisions within 1e-12 s
   (the closing speeds shrink geometrically until they drop below ``closing_tol``); with ``min_speed > 0`` a ball
   struck below ``min_speed`` is stopped at once and becomes an immovable wall, so a ball wedged between it and
   a cushion loses its speed in thousands of micro-collisions at t = 0 instead of moving.
"""
from __future__ import annotations

import pytest

from billiards_env.physics.invariants import ZENO_SPAN, run_case

from .helpers import describe, load_case

#: Most events at one instant accepted for a small scene: a 16-ball break needs well under 200.
REGRESSION_BURST = 2000


@pytest.mark.parametrize("case", [
    "missed_recontact_sliding_pair.json",  # 2 balls on an open table, both moving, e_b = 0.5: overlap 0.14 mm
    "missed_recontact_corner_cushion.json",  # 2 balls at a corner, cushion e = 0, e_b = 1: overlap 0.26 mm
    "missed_recontact_gentle_break_e1.json",  # the standard touching rack at 0.3 m/s, e_b = 1: overlap 0.68 mm
    # fuzz seed 8: a merged (sticky) pair, one of them then hit by a third ball: it opened a gap of 1e-21 m^2
    # (below round-off) before friction pressed it together again: overlap 16 um
    "missed_recontact_pressed_pair.json",
])
def test_no_missed_recontact(case):
    d = load_case(case)
    rep, res = run_case(d)
    assert not {"overlap", "overlap_during", "contact"} & set(rep.violations), describe(rep, d)


@pytest.mark.parametrize("case", [
    "zeno_drag_inelastic_rack.json",  # 15 balls, drag k = 0, e_b = 0: 33,194 events within 5e-13 s
    "zeno_drag_inelastic_cluster.json",  # 6 balls, drag k = 1, e_b = 0: 3,625 events at one instant
    "zeno_min_speed_wedge.json",  # 2 balls, drag, min_speed 0.049: 4,100 events at t = 0, then the cue is at rest
    # found by Hypothesis: the first 6 balls of the rack hit head-on, no friction, e_b = 0, cushion e = 0; ball 2
    # ends wedged between ball 4 and the bottom cushion: 11,236 events within 1.5e-9 s (collision, cushion, ...)
    "zeno_frictionless_rack_e0.json",
    # jaw fuzz (seed 2026, shot 3110; d649595): a WPA jaw table, cushion e = 0: ball 2 hits the top-left corner's jaw
    # face on the left rail and slides along it with its normal velocity at round-off (-1.4e-17 m/s): 19,990
    # zero-speed hits of that face at one instant; fixed by walls.GRAZE
    "zeno_jaw_face_no_restitution.json",
    # jaw fuzz (seed 2026, shot 34510; 582695b): drag k = 0, cushion e = 0, a pair wedged in a corner's throat, each
    # ball against its own jaw face: the jam took out one face's component at a time and put back the other's:
    # 7,365 events within 1.1e-13 s; fixed by walls.cluster_off_walls (the cluster's velocity off every wall)
    "zeno_jaw_wedged_pair.json",
    # jaw fuzz (seed 2026, shot 126636; 0b41001): spin model, a nearly rolling ball (slip 1.5e-5 m/s) settled on a
    # jaw face by the pressed rule, the round-off of its slip's normal part making its acceleration press in by
    # ~1e-12 m/s^2: 19,960 zero-speed hits within 2.4e-10 s; fixed by a tolerance on that scale in exact_spin
    "zeno_jaw_settled_sliding_ball.json",
])
def test_no_inelastic_collapse_storm(case):
    d = load_case(case)
    rep, res = run_case(d, sample_between=False)
    assert "zeno" not in rep.violations, describe(rep, d)
    assert rep.max_burst <= REGRESSION_BURST, (
        f"{rep.max_burst} events within {ZENO_SPAN:g} s of each other (status {res.status}, {res.n_events} events)")
