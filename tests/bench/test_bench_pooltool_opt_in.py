"""pooltool (a 734 MB venv) is installed only when asked (``--with-pooltool``); otherwise its comparison is left
out with a line saying how to include it, and nothing waits for input."""
from __future__ import annotations

import subprocess

import pytest

from benchmarks import pooltool_runner


def test_a_missing_pooltool_is_not_installed_unless_asked(monkeypatch, tmp_path):
    ran = []
    monkeypatch.setattr(pooltool_runner, "DEFAULT_VENV", tmp_path / ".venv-pooltool")
    monkeypatch.setattr(subprocess, "run", lambda *a, **k: ran.append(a) or pytest.fail("nothing may run"))
    version, note = pooltool_runner.ensure_pooltool(tmp_path / ".venv-pooltool" / "bin" / "python")
    assert version is None and not ran
    assert "the comparison with pooltool is left out" in note and "--with-pooltool" in note and "734 MB" in note


@pytest.mark.parametrize("argv, allowed", [([], False), (["--with-pooltool"], True),
                                           (["--no-pooltool-setup"], False)])
def test_only_with_pooltool_allows_the_setup(monkeypatch, argv, allowed):
    import benchmarks.__main__ as cli
    from benchmarks import speed

    seen = {}
    monkeypatch.setattr(speed, "main", lambda out, **kw: seen.update(kw))
    assert cli.main(["--quick", "--only", "pooltool", *argv]) == 0
    assert seen["allow_setup"] is allowed


def test_with_and_without_setup_cannot_both_be_given(capsys):
    import benchmarks.__main__ as cli

    with pytest.raises(SystemExit):
        cli.main(["--with-pooltool", "--no-pooltool-setup"])
    assert "not allowed with argument" in capsys.readouterr().err
