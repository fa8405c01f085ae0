#!/usr/bin/env python3
"""The JSON Schema of the case (`fosls-contact schema case`, both dimensions) and the reader
agree; the result of a solve is valid for the result schema (`fosls-contact schema result`).

Every shipped example and every case in docs/case-format.md is valid for both; every case of
the corpus below is refused by both, except the rules a schema cannot express (expressions,
geometry, cross-field rules), which only the reader checks: those must pass the schema and be
refused by the reader, so the list of them stays honest.
"""
import argparse
import copy
import json
import pathlib
import re
import subprocess
import sys
import tempfile

try:
    import jsonschema
except ImportError:
    sys.exit("python3-jsonschema is missing: install it (docker/install-deps.sh does)")


def base_case():
    return {
        "name": "schema_base",
        "mesh": {"builtin": "square", "size": 0.5, "refinements": 0},
        "material": {"mu": 1, "lambda": 1},
        "boundary": {
            "top": {"type": "dirichlet", "displacement": [0, -0.05]},
            "bottom": {"type": "contact", "obstacle": {"type": "gap", "g": "0.4*(x-0.5)^2"}},
        },
        "solver": {"max_iterations": 2},
    }


def base_case_3d():
    return {
        "name": "schema_base_3d",
        "dimension": 3,
        "mesh": {"builtin": {"name": "box", "cells": [1, 1, 1]}, "refinements": 0},
        "material": {"mu": 1, "lambda": 1},
        "boundary": {
            "top": {"type": "dirichlet", "displacement": [0, 0, -0.01]},
            "bottom": {"type": "contact", "point": [0, 0, 0], "normal": [0, 0, 1]},
        },
        "solver": {"max_iterations": 2},
    }


def setting(pointer, value):
    """A change of the base case: the value at a JSON pointer (None deletes it)."""
    def change(case):
        *parents, last = [p.replace("~1", "/").replace("~0", "~") for p in pointer.split("/")[1:]]
        node = case
        for p in parents:
            node = node[int(p)] if isinstance(node, list) else node.setdefault(p, {})
        if value is None:
            del node[last]
        elif isinstance(node, list):
            node[int(last)] = value
        else:
            node[last] = copy.deepcopy(value)
        return case
    return change


GEOMETRY = {"points": [[0, 0], [1, 0], [1, 1], [0, 1]],
            "curves": [{"type": "line", "points": [0, 1]}, {"type": "line", "points": [1, 2]},
                       {"type": "line", "points": [2, 3]}, {"type": "line", "points": [3, 0]}],
            "groups": {"bottom": [0], "right": [1], "top": [2], "left": [3]}}

# Structural rules: both refuse.
BOTH_REFUSE = [
    ("unknown_top_field", setting("/solvr", {})),
    ("mesh_missing", setting("/mesh", None)),
    ("two_mesh_sources", setting("/mesh/msh", "$MeshFormat\n")),
    ("no_mesh_source", setting("/mesh/builtin", None)),
    ("unknown_builtin", setting("/mesh/builtin", "circle")),
    ("builtin_unknown_parameter", setting("/mesh/builtin", {"name": "hertz", "width": 1})),
    ("builtin_without_name", setting("/mesh/builtin", {"radius": 1})),
    ("contact_fraction_one", setting("/mesh/builtin", {"name": "hertz", "contact_fraction": 1})),
    ("size_zero", setting("/mesh/size", 0)),
    ("size_string", setting("/mesh/size", "0.5")),
    ("refinements_fraction", setting("/mesh/refinements", 1.5)),
    ("refinements_too_many", setting("/mesh/refinements", 9)),
    ("mu_zero", setting("/material/mu", 0)),
    ("lambda_negative", setting("/material/lambda", -1)),
    ("lambda_bad_string", setting("/material/lambda", "infinite")),
    ("both_material_forms", setting("/material/E", 1)),
    ("lambda_missing", setting("/material/lambda", None)),
    ("nu_above_half", setting("/material", {"E": 1, "nu": 0.6})),
    ("body_force_one_value", setting("/body_force", [1])),
    ("body_force_boolean", setting("/body_force", [True, 0])),
    ("empty_boundary", setting("/boundary", {})),
    ("empty_group_name", setting("/boundary/", {"type": "neumann", "traction": [0, 0]})),
    ("control_character_in_name", setting("/name", "a\tb")),
    ("name_too_long", setting("/name", "n" * 201)),
    ("condition_type_unknown", setting("/boundary/top/type", "robin")),
    ("condition_without_type", setting("/boundary/top", {"displacement": [0, 0]})),
    ("dirichlet_with_traction", setting("/boundary/top/traction", [0, 0])),
    ("dirichlet_without_displacement", setting("/boundary/top/displacement", None)),
    ("obstacle_type_unknown", setting("/boundary/bottom/obstacle/type", "wall")),
    ("circle_radius_zero", setting("/boundary/bottom/obstacle",
                                   {"type": "circle", "center": [0, -1], "radius": 0})),
    ("plane_point_three", setting("/boundary/bottom/obstacle",
                                  {"type": "plane", "point": [0, 0, 0], "normal": [0, 1]})),
    ("direction_unknown", setting("/boundary/bottom/direction", "sideways")),
    ("displacement_boolean_component", setting("/boundary/top/displacement", [None, False])),
    ("gap_obstacle_moved", setting("/boundary/bottom/obstacle/displacement", [0, 0.1])),
    ("time_limit_negative", setting("/solver/time_limit_s", -1)),
    ("pressure_without_value", setting("/boundary/left", {"type": "pressure"})),
    ("pressure_as_pair", setting("/boundary/left", {"type": "pressure", "pressure": [0, 1]})),
    ("sweep_without_pointer", setting("/sweep", {"values": [1]})),
    ("sweep_without_values", setting("/sweep", {"pointer": "/material/mu"})),
    ("sweep_text_value", setting("/sweep", {"pointer": "/material/mu", "values": ["2"]})),
    ("expression_too_long", setting("/boundary/top/displacement/1", "x" + " " * 1100)),
    ("weights_c1_zero", setting("/weights", {"c1": 0})),
    ("weights_unknown", setting("/weights", {"c5": 1})),
    ("method_unknown", setting("/solver/method", "cg")),
    ("tolerance_one", setting("/solver/tolerance", 1)),
    ("max_iterations_zero", setting("/solver/max_iterations", 0)),
    ("smoothing_eleven", setting("/solver/pre_smoothing", 11)),
    ("coarse_obstacle_unknown", setting("/solver/coarse_obstacle", "d")),
    ("geometry_empty_points", setting("/mesh", {"geometry": dict(GEOMETRY, points=[])})),
    ("geometry_curve_spline", setting("/mesh", {"geometry": dict(
        GEOMETRY, curves=GEOMETRY["curves"][:3] + [{"type": "spline", "points": [3, 0]}])})),
    ("geometry_negative_index", setting("/mesh", {"geometry": dict(
        GEOMETRY, groups={"bottom": [-1], "right": [1], "top": [2], "left": [3]})})),
]

# The same for a 3D case (base_case_3d): the schema checks it against the 3D rules.
BOTH_REFUSE_3D = [
    ("3d_displacement_of_two", setting("/boundary/top/displacement", [0, -0.01])),
    ("3d_circle_obstacle", setting("/boundary/bottom", {
        "type": "contact", "obstacle": {"type": "circle", "center": [0, 0], "radius": 1}})),
    ("3d_square_builtin", setting("/mesh/builtin", "square")),
    ("3d_geometry", setting("/mesh", {"geometry": GEOMETRY})),
    ("3d_refinements_six", setting("/mesh/refinements", 6)),
    ("3d_point_and_obstacle", setting("/boundary/bottom/obstacle", {"type": "gap", "g": 1})),
    ("3d_body_force_of_two", setting("/body_force", [0, 1])),
]

# Read in 3D, and refused there for now (docs/case-format.md, "3D cases"): the schema accepts.
READER_ONLY_3D = [
    ("3d_friction", setting("/boundary/bottom/friction", {"coefficient": 0.3})),
]

BOTH_ACCEPT_3D = [
    ("3d_tnnmg", setting("/solver/method", "tnnmg")),
    ("3d_pgs", setting("/solver/method", "pgs")),
    ("3d_sphere", setting("/boundary/bottom", {
        "type": "contact", "obstacle": {"type": "sphere", "center": [0.5, 0.5, -10], "radius": 10}})),
    ("3d_expression_body_force", setting("/body_force", [0, 0, "0.01*z"])),
    ("3d_weights_and_units", setting("/weights", {"c3": 0.05})),
    ("3d_time_limit", setting("/solver/time_limit_s", 30)),
    ("3d_load_steps", setting("/load_steps", [{"/material/mu": 2}])),
    ("3d_sweep", setting("/sweep", {"pointer": "/material/mu", "values": [1, 2]})),
    ("3d_c3_auto", setting("/weights", {"c3": "auto"})),
]

# Rules only the reader can check.
READER_ONLY = [
    ("expression_does_not_parse", setting("/boundary/top/displacement/1", "x +* 2")),
    ("expression_unknown_name", setting("/boundary/bottom/obstacle/g", "q")),
    ("expression_not_finite", setting("/boundary/bottom/obstacle/g", "1/x")),
    ("msh_not_msh", setting("/mesh", {"msh": "solid cube"})),
    ("tiny_size", setting("/mesh/size", 1e-5)),
    ("plane_normal_zero", setting("/boundary/bottom/obstacle",
                                  {"type": "plane", "point": [0, 0], "normal": [0, 0]})),
    ("obstacle_normal_with_gap", setting("/boundary/bottom/direction", "obstacle_normal")),
    ("mmg_without_smoothing", setting("/solver", {"pre_smoothing": 0, "post_smoothing": 0})),
    ("displacement_both_null", setting("/boundary/top/displacement", [None, None])),
    ("sweep_of_the_mesh", setting("/sweep", {"pointer": "/mesh/size", "values": [0.25]})),
    ("sweep_of_nothing", setting("/sweep", {"pointer": "/solver/tolerance", "values": [1e-6]})),
    ("sweep_to_an_invalid_value", setting("/sweep", {"pointer": "/material/mu", "values": [1, -1]})),
    ("geometry_index_out_of_range", setting("/mesh", {"geometry": dict(
        GEOMETRY, groups={"bottom": [0], "right": [1], "top": [2], "left": [7]})})),
    ("geometry_curve_in_no_group", setting("/mesh", {"geometry": dict(
        GEOMETRY, groups={"bottom": [0], "right": [1], "top": [2]})})),
    ("geometry_not_closed", setting("/mesh", {"geometry": dict(
        GEOMETRY, curves=GEOMETRY["curves"][:3], groups={"a": [0, 1, 2]})})),
    ("geo_file_in_a_service_case", None),  # see below: the CLI allows geo_file, the schema too
]

# Valid variants: both accept.
BOTH_ACCEPT = [
    ("builtin_object", setting("/mesh/builtin", {"name": "square", "width": 2})),
    ("young_and_poisson", setting("/material", {"E": 2.5, "nu": 0.3})),
    ("incompressible", setting("/material/lambda", "inf")),
    ("expression_body_force", setting("/body_force", ["sin(x)", 0])),
    ("circle_obstacle", setting("/boundary/bottom/obstacle",
                                {"type": "circle", "center": [0.5, -2], "radius": 2})),
    ("obstacle_normal_plane", setting("/boundary/bottom", {
        "type": "contact", "obstacle": {"type": "plane", "point": [0, 0], "normal": [0, 1]},
        "direction": "obstacle_normal"})),
    ("every_solver_field", setting("/solver", {
        "method": "tnnmg", "tolerance": 1e-6, "max_iterations": 2, "smoother": "point",
        "pre_smoothing": 2, "post_smoothing": 0, "coarse_obstacle": "c"})),
    ("geometry", setting("/mesh", {"geometry": GEOMETRY, "size": 0.5})),
    ("integral_float", setting("/mesh/refinements", 1.0)),
    ("roller", setting("/boundary/left", {"type": "dirichlet", "displacement": [0, None]})),
    ("moved_plane", setting("/boundary/bottom/obstacle", {
        "type": "plane", "point": [0, 0], "normal": [0, 1], "displacement": [0, 0.01]})),
    ("time_limit", setting("/solver/time_limit_s", 30)),
    ("pressure", setting("/boundary/left", {"type": "pressure", "pressure": "0.01*y"})),
    ("sweep", setting("/sweep", {"pointer": "/material/mu", "values": [1, 2]})),
]


def reader_refuses(binary, case, work):
    path = work / "case.json"
    path.write_text(json.dumps(case))
    r = subprocess.run([binary, "solve", str(path), "--quiet", "--out", str(work / "r.json")],
                       capture_output=True, text=True, timeout=60)
    if r.returncode not in (0, 2, 3, 4):
        raise AssertionError(f"unexpected exit {r.returncode}: {r.stderr} for {json.dumps(case)[:300]}")
    return r.returncode == 2, r.stderr


def documented_cases(source):
    text = (source / "docs" / "case-format.md").read_text()
    for block in re.findall(r"```json\n(.*?)```", text, re.S):
        if block.startswith("{"):
            yield json.loads(block)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--bin", required=True)
    parser.add_argument("--source", required=True)
    args = parser.parse_args()
    source = pathlib.Path(args.source)
    schema = json.loads(subprocess.run([args.bin, "schema", "case"], capture_output=True,
                                       text=True, check=True).stdout)
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    failures = []

    shipped = sorted((source / "solver" / "examples").glob("*.json"))
    for path in shipped:
        errors = [e.message for e in validator.iter_errors(json.loads(path.read_text()))]
        if errors:
            failures.append(f"shipped example {path.name} fails the schema: {errors[:3]}")
    # 3D cases ("dimension": 3) have the same schema, which checks them by the 3D rules.
    shipped_3d = sorted((source / "solver" / "examples" / "3d").glob("*.json"))
    for path in shipped_3d:
        errors = [e.message for e in validator.iter_errors(json.loads(path.read_text()))]
        if errors:
            failures.append(f"shipped 3D example {path.name} fails the schema: {errors[:3]}")
    without_dimension = json.loads(shipped_3d[0].read_text())
    del without_dimension["dimension"]
    if validator.is_valid(without_dimension):
        failures.append("the schema accepts a 3D case without its dimension as a 2D case")
    documented = list(documented_cases(source))
    for case in documented:
        if not validator.is_valid(case):
            failures.append(f"documented case {case.get('name')} fails the schema")

    with tempfile.TemporaryDirectory() as tmp:
        work = pathlib.Path(tmp)
        for name, change in BOTH_REFUSE + [(n, lambda _, c=c: c(base_case_3d()))
                                           for n, c in BOTH_REFUSE_3D]:
            case = change(base_case())
            refused, _ = reader_refuses(args.bin, case, work)
            if validator.is_valid(case):
                failures.append(f"{name}: the schema accepts it")
            if not refused:
                failures.append(f"{name}: the reader accepts it")
        for name, change in READER_ONLY + [(n, lambda _, c=c: c(base_case_3d()))
                                           for n, c in READER_ONLY_3D]:
            if change is None:
                continue
            case = change(base_case())
            refused, _ = reader_refuses(args.bin, case, work)
            if not validator.is_valid(case):
                failures.append(f"{name}: the schema refuses it; move it to BOTH_REFUSE")
            if not refused:
                failures.append(f"{name}: the reader accepts it")
        for name, change in BOTH_ACCEPT + [(n, lambda _, c=c: c(base_case_3d()))
                                           for n, c in BOTH_ACCEPT_3D]:
            case = change(base_case())
            refused, stderr = reader_refuses(args.bin, case, work)
            errors = [e.message for e in validator.iter_errors(case)]
            if errors:
                failures.append(f"{name}: the schema refuses it: {errors[:2]}")
            if refused:
                failures.append(f"{name}: the reader refuses it: {stderr}")

    # The result of a solve is valid for the result schema, and the schema is strict.
    result_schema = json.loads(subprocess.run([args.bin, "schema", "result"], capture_output=True,
                                              text=True, check=True).stdout)
    jsonschema.Draft202012Validator.check_schema(result_schema)
    result_validator = jsonschema.Draft202012Validator(result_schema)
    with tempfile.TemporaryDirectory() as tmp:
        case = source / "solver" / "examples" / "signorini_square.json"
        out = pathlib.Path(tmp) / "result.json"
        subprocess.run([args.bin, "solve", str(case), "--quiet", "--out", str(out)], check=True)
        result = json.loads(out.read_text())
    errors = [e.message for e in result_validator.iter_errors(result)]
    if errors:
        failures.append(f"the result of signorini_square fails the result schema: {errors[:3]}")
    result["contact"]["surprise"] = 1
    if result_validator.is_valid(result):
        failures.append("the result schema accepts an undocumented field")

    checked = 2 + len(shipped) + len(shipped_3d) + 1 + len(documented) + len(BOTH_REFUSE) + len(
        READER_ONLY) - 1 + len(BOTH_ACCEPT) + len(BOTH_REFUSE_3D) + len(READER_ONLY_3D) + len(
        BOTH_ACCEPT_3D)
    for f in failures:
        print("FAIL:", f)
    print(f"{checked - len(failures)} passed, {len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
