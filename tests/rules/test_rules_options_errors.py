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
