"""Python reads YAML through the library's one YAML reader: an alias inside the value it names
(which made every reader walk for ever) and a line of another file as a key are InputErrors with
the CLI's message, quickly."""
import time

import pytest

import pmdplan

from conftest import cli_error

SHADOW = "root:$6$saltsalt$" + "h" * 86 + ":19000:0:99999:7:::"


@pytest.mark.parametrize("text, where", [("a: &r [*r]\n", "a[0] (line 1)"), ("a: &r {b: *r}\n", "a.b (line 1)"),
                                         ("- &x [*x]\n", "[0][0] (line 1)")])
def test_an_alias_inside_its_own_value_is_an_input_error(tmp_path, cli, text, where):
    task = tmp_path / "cycle.yaml"
    task.write_text(text)
    began = time.monotonic()
    with pytest.raises(pmdplan.InputError) as raised:
        pmdplan.Task.load(str(task))
    assert time.monotonic() - began < 5
    assert where in raised.value.field
    assert "a value cannot contain itself" in raised.value.message
    code, _, stderr = cli("check", task)
    assert code == 2
    assert str(raised.value) == cli_error(stderr)
    with pytest.raises(pmdplan.InputError, match="a value cannot contain itself"):
        pmdplan.SynergyModel.load(str(task))


def test_a_line_of_another_file_is_measured_not_shown(tmp_path):
    task = tmp_path / "shadow.yaml"
    task.write_text(SHADOW + ": 1\n\"\\e[2J\": 2\n")
    with pytest.raises(pmdplan.InputError) as raised:
        pmdplan.Task.load(str(task))
    assert "saltsalt" not in str(raised.value)
    assert "a text of 122 characters" in raised.value.message
