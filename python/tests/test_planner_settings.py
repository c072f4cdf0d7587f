"""Every row of the settings table (include/pmdplan/planning/planner_setting_table.hpp) reaches
Python under one name (the flag with underscores): a property of PlannerSettings with its kind's
type and the table's default, in the stubs and in the docs; bad values raise InputError naming the
property. (The command line and OMPL: tests/cli/planner_settings_cli_test.cpp,
tests/bench/ompl_setting_reach_test.cpp.)"""
import ast
import math
import re

import pytest

import pmdplan
from planner_settings_reference import DOCS, ROOT, STUBS, expected_texts

FIELDS = pmdplan.PlannerSettings.fields()
TYPES = {"float": float, "int": int, "str": str, "bool": bool}
KINDS = {"number": "float", "count": "int", "choice": "str", "switch": "bool"}


def other_value(field, current):
    """A value of the field's type other than `current`."""
    if field["kind"] == "number":
        return 0.25 if current == 0.5 else 0.5
    if field["kind"] == "count":
        return 4 if current == 3 else 3
    if field["kind"] == "switch":
        return not current
    return next(c for c in field["choices"] if c != current)


def test_fields_are_the_table_rows_named_by_their_flags():
    names = [f["name"] for f in FIELDS]
    assert len(set(names)) == len(names) and names
    for field in FIELDS:
        assert field["flag"] == "--" + field["name"].replace("_", "-"), field
        assert KINDS[field["kind"]] == field["type"], field
        assert (field["kind"] in ("choice", "switch")) == bool(field["choices"]), field
        assert field["help"], field


def test_every_row_is_a_typed_property_with_the_tables_default():
    properties = {name for name, value in vars(pmdplan.PlannerSettings).items() if isinstance(value, property)}
    assert properties == {f["name"] for f in FIELDS}, "a property the table lacks, or a row without a property"
    pmd, full = pmdplan.PlannerSettings("pmd"), pmdplan.PlannerSettings("full")
    for field in FIELDS:
        value = getattr(pmd, field["name"])
        assert type(value) is TYPES[field["type"]], field["name"]
        assert value == field["default"] and getattr(full, field["name"]) == field["default_full"], field["name"]
        if field["kind"] == "choice":
            assert value in field["choices"]
        doc = getattr(pmdplan.PlannerSettings, field["name"]).__doc__
        assert field["help"] in doc and field["flag"] in doc and repr(field["default"]) in doc, doc


def test_every_row_is_set_and_read_back_alone():
    for field in FIELDS:
        settings = pmdplan.PlannerSettings()
        before = {f["name"]: getattr(settings, f["name"]) for f in FIELDS}
        value = other_value(field, before[field["name"]])
        setattr(settings, field["name"], value)
        assert getattr(settings, field["name"]) == value, field["name"]
        for other in FIELDS:
            if other is not field:
                assert getattr(settings, other["name"]) == before[other["name"]], (field["name"], other["name"])
        assert pmdplan.PlannerSettings(**{field["name"]: value}) == settings
        assert settings != pmdplan.PlannerSettings()


def test_repr_lists_every_setting_and_reads_back():
    settings = pmdplan.PlannerSettings("full", rho_a=0.02, rho_a_growth="linear", smooth=False, time_limit=math.inf)
    text = repr(settings)
    for field in FIELDS:
        assert f"{field['name']}=" in text
    assert "rho_a_growth='linear'" in text and "smooth=False" in text and "arm_trials=20" in text
    assert eval(text, {"PlannerSettings": pmdplan.PlannerSettings, "inf": math.inf}) == settings


def bad_value(field):
    return {"number": math.nan, "count": -1, "choice": "no-such-choice", "switch": "on"}[field["kind"]]


def test_bad_values_raise_input_error_naming_the_property():
    for field in FIELDS:
        settings = pmdplan.PlannerSettings()
        before = getattr(settings, field["name"])
        for value in (bad_value(field), [1]):
            with pytest.raises(pmdplan.InputError) as raised:
                setattr(settings, field["name"], value)
            assert raised.value.field == field["name"], (field["name"], value)
            assert "--" not in str(raised.value)
        assert getattr(settings, field["name"]) == before
        with pytest.raises(pmdplan.InputError) as raised:
            pmdplan.PlannerSettings(**{field["name"]: bad_value(field)})
        assert raised.value.field == field["name"]


def test_out_of_range_values_name_the_property_in_check_and_plan(can_on_table):
    for name, value in (("rho_a", 2.0), ("neighbour_threshold", 0.0), ("lazy_radius", 0.0),
                        ("connect_arm_growth", 0.5), ("time_limit", -1.0), ("max_pmds", 0)):
        settings = pmdplan.PlannerSettings(**{name: value})
        with pytest.raises(pmdplan.InputError) as raised:
            settings.check()
        assert raised.value.field == name and str(raised.value).startswith(name + ": ")
    with pytest.raises(pmdplan.InputError) as raised:
        pmdplan.plan(can_on_table, settings=pmdplan.PlannerSettings(neighbours=0))
    assert raised.value.field == "neighbours"
    with pytest.raises(pmdplan.InputError) as raised:
        pmdplan.PlannerSettings("astar")
    assert raised.value.field == "planner"


def test_old_and_unknown_names_are_refused():
    settings = pmdplan.PlannerSettings()
    for old in ("initial_arm_half_size", "neighbour_count", "arm_box_growth", "neighbour_threshold_factor",
                "min_sweep_visits"):
        with pytest.raises(AttributeError):
            setattr(settings, old, 1)
        with pytest.raises(TypeError, match="rho_a"):
            pmdplan.PlannerSettings(**{old: 1})


def stub_class():
    tree = ast.parse(STUBS.read_text())
    return next(node for node in tree.body if isinstance(node, ast.ClassDef) and node.name == "PlannerSettings")


def test_the_stubs_list_every_row_with_its_type():
    cls = stub_class()
    annotated = {node.target.id: ast.unparse(node.annotation) for node in cls.body if isinstance(node, ast.AnnAssign)}
    assert annotated == {f["name"]: f["type"] for f in FIELDS}
    init = next(node for node in cls.body if isinstance(node, ast.FunctionDef) and node.name == "__init__")
    keywords = {arg.arg: ast.unparse(arg.annotation) for arg in init.args.kwonlyargs}
    assert keywords == {f["name"]: f["type"] for f in FIELDS}
    assert [arg.arg for arg in init.args.args] == ["self", "planner"]


def test_the_generated_stubs_and_docs_are_up_to_date():
    for path, (current, expected) in expected_texts(FIELDS).items():
        assert current == expected, f"{path.relative_to(ROOT)}: run python/tests/planner_settings_reference.py --write"


def test_docs_name_only_flags_of_the_table():
    flags = {f["flag"] for f in FIELDS}
    deviations = (ROOT / "docs" / "deviations.md").read_text()
    table_flags = re.findall(r"^\| `(--[a-z-]+)` \|", deviations, re.MULTILINE)
    assert table_flags and set(table_flags) <= flags
    for page in list((ROOT / "docs").glob("*.md")) + [ROOT / "README.md"]:
        for flag in re.findall(r"--(?:lazy|connect)-[a-z-]+", page.read_text()):
            assert flag in flags, (page.name, flag)
    docs = DOCS.read_text()
    for field in FIELDS:
        assert f"| `{field['name']}` | `{field['flag']}` |" in docs
