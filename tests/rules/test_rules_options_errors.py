"""An unknown ruleset option gets the error every other config error has: the allowed keys and a did-you-mean."""
from __future__ import annotations

import pytest

from billiards_env.rules import EightBallOptions, NineBallOptions, RulesError


@pytest.mark.parametrize("cls, typo, meant", [(NineBallOptions, "push_outt", "push_out"),
                                              (EightBallOptions, "call_8", "call_eight")])
def test_unknown_option_names_the_valid_ones(cls, typo, meant):
    with pytest.raises(RulesError, match=rf"{cls.__name__}: unknown option '{typo}'; did you mean '{meant}'\? "
                                         r"valid options: .*three_foul_rule"):
        cls(**{typo: True})
    assert getattr(cls(**{meant: False}), meant) is False  # the known keys still work, by keyword


def test_env_config_reports_it_as_a_config_error():
    gym = pytest.importorskip("gymnasium")
    import billiards_env  # noqa: F401
    from billiards_env.envs.config import ConfigError

    with pytest.raises(ConfigError, match=r"^rules: NineBallOptions: unknown option 'push_outt'; did you mean "
                                          r"'push_out'\?"):
        gym.make("Billiards9Ball-v0", rules={"push_outt": True})


@pytest.mark.parametrize("game", ["nine_ball", "eight_ball", "snooker", "three_cushion"])
def test_every_game_refuses_a_typo_the_same_way(game):
    """One mechanism for every game's options (the session's), so snooker and three-cushion say what 9-ball says."""
    from billiards_env.games.registry import game_spec

    session = game_spec(game).session_class
    name = session.options_type.__name__
    with pytest.raises(RulesError, match=rf"^{name}: unknown option 'target_pionts'; (did you mean '\w+'\? )?"
                                         r"valid options: \w+"):
        session.options({"target_pionts": 5})
    with pytest.raises(RulesError, match=r"rules must be a mapping .* got list"):
        session.options([1, 2])


@pytest.mark.parametrize("env_id, typo, meant", [("BilliardsSnooker-v0", "miss_limt", "miss_limit"),
                                                 ("BilliardsThreeCushion-v0", "target_pionts", "target_points")])
def test_snooker_and_three_cushion_configs_give_the_did_you_mean(env_id, typo, meant):
    gym = pytest.importorskip("gymnasium")
    import billiards_env  # noqa: F401
    from billiards_env.envs.config import ConfigError

    with pytest.raises(ConfigError, match=rf"^rules: \w+Options: unknown option '{typo}'; did you mean '{meant}'\? "
                                          r"valid options: "):
        gym.make(env_id, rules={typo: 5})
