#!/usr/bin/env python3
"""The folder layers of the solver library, checked on the sources.

    tests/check_layers.py --build build               # check (ctest: layer_includes, label style)
    tests/check_layers.py --build build --write-doc   # regenerate the graph in the docs

Reads what the build allows from two files that solver/CMakeLists.txt writes at configure
time: build/layers.txt ("<folder>: <folders it links>", one line per library) and
build/public_headers.txt (the headers programs outside the library may include). Fails when

  - a file in solver/<folder>/ includes a header of a folder its library does not link,
    directly or through the libraries it links (the compiler fails too: each library sees
    only its own include roots; this check also catches "../" paths and names the file);
  - a file in solver/cli/, service/ or examples/ includes a library header that is not public;
  - the folder graph of the includes or of the links has a cycle;
  - the generated graph in docs/architecture.md differs from the includes.
"""
import argparse
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOC = os.path.join(ROOT, "docs", "architecture.md")
BEGIN, END = "<!-- layers:begin (tests/check_layers.py --write-doc) -->", "<!-- layers:end -->"
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def read_links(build):
    links = {}
    with open(os.path.join(build, "layers.txt")) as f:
        for line in f:
            if ":" in line:
                folder, deps = line.split(":", 1)
                links[folder.strip()] = deps.split()
    return links


def closure(links, folder):
    seen, stack = set(), list(links.get(folder, []))
    while stack:
        d = stack.pop()
        if d not in seen:
            seen.add(d)
            stack.extend(links.get(d, []))
    return seen


def sources(folder):
    """Every source below `folder`, its subfolders' included (the case layer's by role)."""
    for where, dirs, names in sorted(os.walk(folder)):
        dirs.sort()
        for name in sorted(names):
            if name.endswith((".cpp", ".hpp")):
                yield os.path.join(where, name)


def includes(path):
    """The project headers a file includes, as paths relative to solver/ when they are there."""
    with open(path) as f:
        text = f.read()
    for inc in INCLUDE.findall(text):
        local = os.path.normpath(os.path.join(os.path.dirname(path), inc))
        if os.path.exists(local):
            yield os.path.relpath(local, os.path.join(ROOT, "solver")), inc
        else:
            yield os.path.normpath(inc), inc


def find_cycle(graph):
    state = {}

    def visit(n, path):
        state[n] = 1
        for m in sorted(graph.get(n, ())):
            if state.get(m) == 1:
                return path + [n, m]
            if m not in state:
                c = visit(m, path + [n])
                if c:
                    return c
        state[n] = 2
        return None

    for n in sorted(graph):
        if n not in state:
            c = visit(n, [])
            if c:
                return c[c.index(c[-1]):]
    return None


def check(build):
    links = read_links(build)
    with open(os.path.join(build, "public_headers.txt")) as f:
        public = {line.strip() for line in f if line.strip()}
    problems, graph = [], {folder: set() for folder in links}
    for folder in links:
        allowed = closure(links, folder) | {folder}
        for path in sources(os.path.join(ROOT, "solver", folder)):
            rel = os.path.relpath(path, os.path.join(ROOT, "solver"))
            for target, written in includes(path):
                target_folder = target.split("/")[0] if "/" in target else folder
                if target_folder not in links:
                    continue  # a header outside the library (none today)
                if target_folder not in allowed:
                    problems.append(
                        f"solver/{rel}: #include \"{written}\" reaches into {target_folder}/, "
                        f"which the {folder} layer does not link (it may use: "
                        f"{', '.join(sorted(allowed))}); move the code down a layer or pass "
                        "what it needs in a type of this layer")
                elif target_folder != folder:
                    graph[folder].add(target_folder)
    for where, own in (("solver/cli", "cli"), ("service", None), ("examples", None)):
        for path in sources(os.path.join(ROOT, where)):
            rel = os.path.relpath(path, ROOT)
            for target, written in includes(path):
                folder = target.split("/")[0] if "/" in target else None
                if folder is None or folder == own or folder not in links:
                    continue
                if target not in public:
                    problems.append(
                        f"{rel}: #include \"{written}\" is not a public header of the library "
                        f"(public: {', '.join(sorted(public))}); use the case layer's API "
                        "(case/*.hpp) or add an entry header to FOSLS_PUBLIC_ENTRY_HEADERS in "
                        "solver/CMakeLists.txt")
    for name, g in (("includes", graph), ("links", {k: set(v) for k, v in links.items()})):
        cycle = find_cycle(g)
        if cycle:
            problems.append(f"the folder graph of the {name} has a cycle: {' → '.join(cycle)}")
    return problems, graph, links


def doc_section(graph, links):
    order = list(links)  # the order of solver/CMakeLists.txt: lower layers first
    lines = [BEGIN, "", "```mermaid", "graph BT"]
    for folder in order:
        for dep in sorted(graph[folder], key=order.index):
            lines.append(f"  {folder} --> {dep}")
    lines += ["  cli --> case", "  service --> case", "```", "",
              "| library | folder | includes headers of | links (CMake) |",
              "|---|---|---|---|"]
    for folder in order:
        used = ", ".join(sorted(graph[folder], key=order.index)) or "—"
        linked = ", ".join(links[folder]) or "—"
        lines.append(f"| `fosls_{folder}` | `solver/{folder}/` | {used} | {linked} |")
    lines += ["| `fosls_cli` | `solver/cli/` | public headers | `fosls` |",
              "| `fosls_service` | `service/` | public headers | `fosls` |", "", END]
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--write-doc", action="store_true")
    args = parser.parse_args()
    problems, graph, links = check(args.build)
    section = doc_section(graph, links)
    with open(DOC) as f:
        doc = f.read()
    if BEGIN not in doc or END not in doc:
        problems.append(f"docs/architecture.md: no generated graph between {BEGIN} and {END}")
    else:
        start, end = doc.index(BEGIN), doc.index(END) + len(END)
        if doc[start:end] != section:
            if args.write_doc:
                with open(DOC, "w") as f:
                    f.write(doc[:start] + section + doc[end:])
                print("docs/architecture.md: graph rewritten")
            else:
                problems.append("docs/architecture.md: the layer graph differs from the "
                                "includes; run tests/check_layers.py --build build --write-doc")
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
