#!/usr/bin/env python3
"""The own-mesh workflow of docs/case-format.md, run as documented: the .geo file and the case
are taken from the document, meshed with the gmsh program, solved with mesh.msh_file and with
--msh. Fails (never skips) when gmsh is missing: docker/install-deps.sh installs it."""
import argparse
import json
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile


def blocks(text, language):
    return re.findall(r"```" + language + r"\n(.*?)```", text, re.S)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--bin", required=True)
    parser.add_argument("--source", required=True)
    args = parser.parse_args()
    gmsh = shutil.which("gmsh")
    if not gmsh:
        print("FAIL: the gmsh program is missing (Debian package gmsh; docker/install-deps.sh)")
        print("0 passed, 1 failed")
        return 1
    doc = (pathlib.Path(args.source) / "docs" / "case-format.md").read_text()
    geo = blocks(doc, "geo")
    cases = [json.loads(b) for b in blocks(doc, "json")
             if b.startswith("{") and "msh_file" in json.loads(b)["mesh"]]
    failures = []
    if len(geo) != 1 or len(cases) != 1:
        failures.append(f"expected one .geo and one msh_file case in the doc, got {len(geo)}, "
                        f"{len(cases)}")
        geo, cases = geo[:1], cases[:1]
    with tempfile.TemporaryDirectory() as tmp:
        work = pathlib.Path(tmp)
        (work / "block.geo").write_text(geo[0])
        subprocess.run([gmsh, "-2", "-format", "msh41", "block.geo", "-o", "block.msh"],
                       cwd=work, check=True, capture_output=True, timeout=120)
        (work / "cases").mkdir()
        case = cases[0]
        # The case file lives elsewhere: msh_file is taken relative to the case's folder.
        case["mesh"]["msh_file"] = "../" + case["mesh"]["msh_file"]
        (work / "cases" / "block_case.json").write_text(json.dumps(case))
        runs = {
            "msh_file": [args.bin, "solve", str(work / "cases" / "block_case.json"), "--quiet",
                         "--out", str(work / "r1.json")],
            "--msh": [args.bin, "solve", "-", "--quiet", "--msh", str(work / "block.msh"),
                      "--out", str(work / "r2.json")],
        }
        square = dict(case, mesh={"builtin": "square", "refinements": 2})
        results = {}
        for name, command in runs.items():
            r = subprocess.run(command, input=json.dumps(square), capture_output=True, text=True,
                               timeout=300, cwd=tmp)
            if r.returncode != 0:
                failures.append(f"{name}: exit {r.returncode}: {r.stderr}")
                continue
            results[name] = json.loads((work / ("r1.json" if name == "msh_file" else
                                                "r2.json")).read_text())
        for name, result in results.items():
            if result["mesh"]["source"] != "msh_file":
                failures.append(f"{name}: mesh.source is {result['mesh']['source']}")
            if not result["contact"]["force"][1] > 0:
                failures.append(f"{name}: no upward contact force: {result['contact']['force']}")
        if len(results) == 2 and results["msh_file"]["dofs"] != results["--msh"]["dofs"]:
            failures.append("msh_file and --msh solved different meshes")
        # The service's rules refuse local paths; the command line reports a missing file.
        missing = dict(case, mesh={"msh_file": "no_such.msh"})
        r = subprocess.run([args.bin, "solve", "-", "--quiet"], input=json.dumps(missing),
                           capture_output=True, text=True, timeout=60, cwd=tmp)
        if r.returncode != 2 or "/mesh/msh_file" not in r.stderr:
            failures.append(f"a missing msh_file: exit {r.returncode}: {r.stderr}")
    for f in failures:
        print("FAIL:", f)
    print(f"{4 - len(failures)} passed, {len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
