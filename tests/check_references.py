#!/usr/bin/env python3
"""Every reference a doc or a comment makes exists.

Checked in README.md and docs/*.md (all text) and in the comments of the sources (solver/,
service/, tests/, web/, clients/, docker/):

- file paths: `solver/…`, `service/…`, `docs/…`, `tests/…`, `web/…`, `clients/…`,
  `docker/…` (globs such as `solver/post/fe_field.*` allowed), paths inside solver/ written
  from a layer (`solvers/galerkin_chain.hpp`), and bare file names (`case_runner.cpp`)
  anywhere in the tree (folders .gitignore names, such as web/node_modules, count as there);
- Markdown links to files of the repository, and their #anchors;
- sections: `method.md §4.1` needs a heading "4.1" there; `docs/service.md, "Isolation"` and
  `README, "Decisions"` a heading that contains the quoted words or a bold lead-in that
  starts with them;
- command lines in code spans and code blocks: `fosls-contact <subcommand>` must be a subcommand
  of the program, and every `--flag` must be one the command's program defines (CLI11 options
  of fosls-contact, fosls-serve, fosls-worker, ...; argparse options of a script).

Prints one line per broken reference and exits 1 if there is any. `--root DIR` checks another
checkout (the self-test copies the tree and breaks a reference on purpose).
"""
import argparse
import os
import re
import subprocess
import sys
from pathlib import Path

TOP_DIRS = ("solver", "service", "docs", "tests", "web", "clients", "docker", ".ci")
LAYERS = ("core", "process", "mesh", "mesher", "fem", "assembly", "solvers", "post", "case", "cli")
CODE_SUFFIXES = {".cpp", ".hpp", ".h", ".js", ".mjs", ".py", ".sh", ".cmake", ".txt", ".yml",
                 ".yaml", ".css"}
FILE_EXTS = r"(?:hpp|cpp|py|sh|mjs|js|md|cmake|json)"
# Programs of the project and where their options are defined (string literals "--flag").
PROGRAMS = {
    "fosls-contact": ["solver/cli"],
    "fosls-serve": ["service"],
    "fosls-worker": ["service"],
    "fosls-solve-job": ["service"],
    "fosls-mesher": ["solver/mesher"],
    "fosls-bench-assembly": ["tests/benchmarks/assembly_bench.cpp"],
    "fosls-bench-displacement": ["tests/benchmarks/displacement_fem.cpp"],
}
COMMON_FLAGS = {"--help", "--version"}
CHECKED = []  # the command lines checked, for --verbose
WRAPPERS = {"heaptrack", "time", "nice", "valgrind", "sudo", "perf", "env", "python3", "bash",
            "record", "stat"}


def tracked_files(root):
    try:
        out = subprocess.run(["git", "ls-files", "--cached", "--others", "--exclude-standard"],
                             cwd=root, capture_output=True, text=True, check=True).stdout
        out = out.split("\n")
        files = [f for f in out if f and (root / f).is_file()]
        if files:
            return files
    except (OSError, subprocess.CalledProcessError):
        pass
    files = []
    for d, dirs, names in os.walk(root):
        dirs[:] = [x for x in dirs if x not in ("build", ".git", "node_modules")
                   and not x.startswith("build")]
        files += [str((Path(d) / n).relative_to(root)) for n in names]
    return files


def gitignored_dirs(root):
    """Folders the build makes (web/dist) or .gitignore names: cited, never tracked."""
    dirs = {"web/dist"}
    gi = root / ".gitignore"
    if gi.is_file():
        for line in gi.read_text().split("\n"):
            line = line.strip().strip("/")
            if line and not line.startswith(("#", "!")) and "*" not in line:
                dirs.add(line)
    return dirs


def c_comments(text):
    """(line number, text) of the // and /* */ comments of C-like source, outside strings."""
    out, in_block, i, line = [], False, 0, 1
    quote = None
    while i < len(text):
        c = text[i]
        if c == "\n":
            line += 1
            quote = None  # no multi-line strings in our sources (raw strings aside)
        if in_block:
            end = text.find("*/", i)
            end = len(text) if end < 0 else end
            chunk = text[i:end]
            for k, part in enumerate(chunk.split("\n")):
                out.append((line + k, part))
            line += chunk.count("\n")
            i = end + 2
            in_block = False
            continue
        if quote:
            if c == "\\":
                i += 2
                continue
            if c == quote:
                quote = None
        elif c in "\"'" and not (c == "'" and i > 0 and text[i - 1].isalnum()):
            quote = c
        elif text.startswith("//", i):
            end = text.find("\n", i)
            end = len(text) if end < 0 else end
            out.append((line, text[i + 2:end]))
            i = end
            continue
        elif text.startswith("/*", i):
            in_block = True
            i += 2
            continue
        i += 1
    return out


def hash_comments(text):
    return [(n, line.split("#", 1)[1]) for n, line in enumerate(text.split("\n"), 1)
            if line.lstrip().startswith("#") and not line.lstrip().startswith("#!")]


def texts_of(root, rel):
    """(line, text) pieces of a file that are prose: all of a Markdown file, comments of code."""
    path = root / rel
    suffix = path.suffix
    if suffix == ".md":
        return list(enumerate(path.read_text(errors="replace").split("\n"), 1))
    if suffix not in CODE_SUFFIXES and path.name not in ("Dockerfile", "run"):
        return []
    text = path.read_text(errors="replace")
    if suffix in (".cpp", ".hpp", ".h", ".js", ".mjs", ".css"):
        return c_comments(text)
    return hash_comments(text)


def slug(heading):
    """GitHub's anchor of a heading."""
    h = re.sub(r"[`*]|<[^>]+>", "", heading).strip().lower()
    h = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", h)
    h = re.sub(r"[^\w\- ]", "", h)
    return h.replace(" ", "-")


class Docs:
    def __init__(self, root):
        self.root = root
        self.cache = {}

    def headings(self, rel):
        if rel not in self.cache:
            text = (self.root / rel).read_text(errors="replace")
            heads, bold, fence = [], [], False
            for line in text.split("\n"):
                if line.startswith("```"):
                    fence = not fence
                if fence:
                    continue
                m = re.match(r"#+\s+(.*)", line)
                if m:
                    heads.append(m.group(1).strip())
                bold += re.findall(r"\*\*([^*]+)\*\*", line)
            anchors, seen = set(), {}
            for h in heads:
                s = slug(h)
                n = seen.get(s, 0)
                seen[s] = n + 1
                anchors.add(s if n == 0 else f"{s}-{n}")
            # Explicit anchors (<a id="…">) count as well.
            anchors |= set(re.findall(r"<a (?:id|name)=\"([^\"]+)\"", text))
            self.cache[rel] = (heads, bold, anchors)
        return self.cache[rel]

    def has_section_number(self, rel, number):
        return any(re.match(re.escape(number) + r"(\.|\s|$)", h) for h in self.headings(rel)[0])

    def has_named_section(self, rel, name):
        heads, bold, _ = self.headings(rel)
        key = norm(name)
        strip_number = lambda h: re.sub(r"^[0-9.]+\s+", "", h)
        return any(key in norm(strip_number(h)) for h in heads) or any(
            norm(b).startswith(key) for b in bold)


def norm(s):
    return re.sub(r"\s+", " ", re.sub(r"[`*]", "", s)).strip().lower().rstrip(".:")


def program_flags(root, files):
    flags = {}
    for prog, places in PROGRAMS.items():
        found = set(COMMON_FLAGS)
        for place in places:
            for f in files:
                if (f == place or f.startswith(place + "/")) and f.endswith((".cpp", ".hpp")):
                    text = (root / f).read_text(errors="replace")
                    for lit in re.findall(r"\"([^\"\n]*)\"", text):
                        found |= set(re.findall(r"--[a-z0-9][a-z0-9-]*", lit))
        flags[prog] = found
    subs = set()
    for f in files:
        if f.startswith("solver/cli/") and f.endswith(".cpp"):
            subs |= set(re.findall(r"add_subcommand\(\s*\"([a-z-]+)\"",
                                   (root / f).read_text(errors="replace")))
    return flags, subs


def command_spans(piece, in_code_block):
    """Command-line candidates: `code spans`, or the whole line inside a code block."""
    if in_code_block:
        return [piece]
    return re.findall(r"`([^`]+)`", piece)


PROG_RE = re.compile(r"\s(?:[\w.-]*/)*(" + "|".join(re.escape(p) for p in PROGRAMS) +
                     r"|[\w./-]+\.(?:py|sh))")


def check_command(span, root, flags, subs, files_set):
    problems = []
    # The command is the span's first word after environment settings and wrappers that run
    # another program (`OMP_WAIT_POLICY=passive heaptrack fosls-contact solve`).
    words = span.strip().lstrip("$ ").split()
    while words and (re.fullmatch(r"[A-Z_][A-Z0-9_]*=\S*", words[0]) or words[0] in WRAPPERS):
        words = words[1:]
    if not words:
        return problems
    m = PROG_RE.fullmatch(" " + words[0])
    if not m:
        return problems
    prog = m.group(1)
    rest = " " + " ".join(words[1:])
    CHECKED.append(span)
    if prog in PROGRAMS:
        known = flags[prog]
        if prog == "fosls-contact":
            words = rest.split()
            if words and re.fullmatch(r"[a-z][a-z-]*", words[0]) and words[0] not in subs:
                problems.append(f"`fosls-contact {words[0]}`: no such subcommand")
    else:
        path = words[0][2:] if words[0].startswith("./") else words[0]
        same_name = [f for f in files_set if f.endswith("/" + Path(path).name)]
        script = path if path in files_set else (same_name[0] if len(same_name) == 1 else None)
        if script is None:
            return problems  # a path the file check reports, or one name of several scripts
        known = set(COMMON_FLAGS) | set(re.findall(r"--[a-z0-9][a-z0-9-]*",
                                                   (root / script).read_text(errors="replace")))
    # Flags up to the end of the command (a pipe, a redirection or a shell separator ends it).
    rest = re.split(r"\s(?:\||&&|;|>)\s", rest)[0]
    for flag in re.findall(r"(?:^|[\s\[(|])(--[a-z0-9][a-z0-9-]*)", rest):
        if flag not in known:
            problems.append(f"`{prog} … {flag}`: {prog} has no option {flag}")
    return problems


SELF_TEST_TREE = {
    "solver/cli/main.cpp": 'app.add_subcommand("solve", "x"); opt("--out,-o");\n',
    "solver/solvers/smoother.hpp": "// See docs/method.md §4.1 and solvers/smoother.hpp.\n",
    "tests/tool.py": 'p.add_argument("--levels")\n',
    "docs/method.md": "# Method\n\n## 4. Cycle\n\n### 4.1 Smoothers\n\n**Bold lead** text.\n",
    "README.md": """# Top

## Use

    build/bin/fosls-contact solve case.json --out r.json
    tests/tool.py --levels 4

Good: `solver/solvers/smoother.hpp`, `solver/solvers/smoother.*`, [m](docs/method.md#41-smoothers),
docs/method.md, "Bold lead"; docs/method.md, "Smoothers"; README, "Use"; smoother.hpp.
""",
}
# Each broken reference, appended to README.md, and the words its report must contain.
SELF_TEST_BROKEN = [
    ("`solver/solvers/gone.hpp`", "solver/solvers/gone.hpp does not exist"),
    ("`solvers/gone.cpp`", "solvers/gone.cpp does not exist"),
    ("case_schema.hpp", "case_schema.hpp does not exist"),
    ("[m](docs/gone.md)", "docs/gone.md does not exist"),
    ("[m](docs/method.md#5-gone)", "no heading #5-gone"),
    ("docs/method.md §5.1", "method.md has no section 5.1"),
    ('docs/method.md, "Gone"', 'method.md has no section "Gone"'),
    ('README, "Gone"', 'README has no section "Gone"'),
    ("`fosls-contact solve x.json --dry-run`", "fosls-contact has no option --dry-run"),
    ("`fosls-contact bench x`", "`fosls-contact bench`: no such subcommand"),
    ("`tests/tool.py --gone`", "has no option --gone"),
]


def self_test():
    import tempfile
    script = Path(__file__).resolve()
    failures = []

    def run(root):
        r = subprocess.run([sys.executable, str(script), "--root", str(root)],
                           capture_output=True, text=True)
        return r.returncode, r.stdout

    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        for rel, text in SELF_TEST_TREE.items():
            (root / rel).parent.mkdir(parents=True, exist_ok=True)
            (root / rel).write_text(text)
        code, out = run(root)
        if code != 0:
            failures.append("the good tree fails:\n" + out)
        for ref, expected in SELF_TEST_BROKEN:
            (root / "README.md").write_text(SELF_TEST_TREE["README.md"] + ref + "\n")
            code, out = run(root)
            if code != 1 or expected not in out:
                failures.append(f"{ref!r} not reported as {expected!r}:\n{out}")
    for f in failures:
        print(f)
    print(f"self-test: {len(SELF_TEST_BROKEN)} broken references, {len(failures)} failures")
    return 1 if failures else 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--root", default=Path(__file__).resolve().parent.parent, type=Path)
    ap.add_argument("--verbose", action="store_true", help="list the command lines checked")
    ap.add_argument("--self-test", action="store_true",
                    help="check a small tree with known good and broken references")
    args = ap.parse_args()
    if args.self_test:
        return self_test()
    root = args.root.resolve()
    files = tracked_files(root)
    files = [f for f in files if "node_modules/" not in f and not f.startswith("build")]
    files_set = set(files)
    dirs = {str(Path(f).parent) for f in files}
    dirs |= {str(p) for f in files for p in Path(f).parents}
    basenames = {Path(f).name for f in files}
    flags, subs = program_flags(root, files)
    docs = Docs(root)

    ignored = gitignored_dirs(root)

    def exists(path):
        path = path.rstrip("/").rstrip(".,:;")
        if any(path == d or path.startswith(d + "/") for d in ignored):
            return True  # generated (web/dist/ by web/build.sh) or installed, not in git
        if any(re.fullmatch(r"[A-Z][A-Z_]+(\.\w+)?", part) for part in path.split("/")):
            return True  # a placeholder: solver/examples/NAME.json
        if any(ch in path for ch in "*?["):
            return any(Path(f).match(path) for f in files) or any(
                Path(d).match(path) for d in dirs)
        return path in files_set or path in dirs

    scanned = [f for f in files if f == "README.md" or f.startswith(TOP_DIRS)]
    problems = []
    for rel in scanned:
        is_md = rel.endswith(".md")
        in_block = False
        for line_no, piece in texts_of(root, rel):
            where = f"{rel}:{line_no}"
            code_line = False
            if is_md:
                if piece.startswith("```"):
                    in_block = not in_block
                    continue
                code_line = in_block or piece.startswith("    ") and not piece.lstrip().startswith(
                    ("-", "*", "|")) and not re.match(r"\s+\d+\.", piece)
            # File paths from the top of the repository.
            for m in re.finditer(r"(?<![\w./<-])((?:" + "|".join(re.escape(d) for d in TOP_DIRS) +
                                 r")/[\w./*-]*)", piece):
                path = m.group(1).rstrip(".")
                tail = piece[m.end():m.end() + 1]
                if tail in "<{…" and tail:
                    continue  # a template such as solver/<folder>
                if path.endswith("/") and tail == "":
                    pass
                if not exists(path):
                    problems.append(f"{where}: {path} does not exist")
            # Paths inside solver/ written from a layer folder, with a file extension.
            for m in re.finditer(r"(?<![\w./<-])((?:" + "|".join(LAYERS) + r")/[\w-]+\.(?:"
                                 r"hpp|cpp|\*))(?![\w/])", piece):
                path = m.group(1)
                if not (exists("solver/" + path) or exists(path)):
                    problems.append(f"{where}: {path} does not exist (in solver/)")
            # Bare file names.
            for m in re.finditer(r"(?<![\w./<>*-])([\w-]+\.(?:hpp|cpp))(?![\w/])", piece):
                if m.group(1) not in basenames:
                    problems.append(f"{where}: {m.group(1)} does not exist")
            # Sections by number.
            for m in re.finditer(r"(?<![\w/-])(?:docs/)?([\w-]+\.md)\)?,?\s*§\s?(\d+(?:\.\d+)*)",
                                 piece):
                doc = "docs/" + m.group(1)
                if doc in files_set and not docs.has_section_number(doc, m.group(2)):
                    problems.append(f"{where}: {m.group(1)} has no section {m.group(2)}")
            # Sections by name.
            for m in re.finditer(r"(?<![\w/-])((?:docs/)?[\w-]+\.md|README)\)?,?\s*"
                                 r"[\"“]([^\"”]+)[\"”]", piece):
                name = m.group(1)
                doc = "README.md" if name == "README" else (
                    name if name.startswith("docs/") or name == "README.md" else "docs/" + name)
                if doc not in files_set:
                    continue
                if not docs.has_named_section(doc, m.group(2)):
                    problems.append(f"{where}: {name} has no section \"{m.group(2)}\"")
            if is_md:
                for m in re.finditer(r"\]\(([^)\s]+)\)", piece):
                    target = m.group(1)
                    if re.match(r"[a-z]+:", target):
                        continue
                    path, _, anchor = target.partition("#")
                    full = os.path.normpath(os.path.join(os.path.dirname(rel), path)) \
                        if path else rel
                    if not exists(full):
                        problems.append(f"{where}: link to {target}: {full} does not exist")
                    elif anchor and full.endswith(".md") and anchor not in docs.headings(full)[2]:
                        problems.append(f"{where}: link to {target}: no heading #{anchor}")
            for span in command_spans(piece, code_line):
                problems += [f"{where}: {p}" for p in check_command(span, root, flags, subs,
                                                                     files_set)]
    if args.verbose:
        print("\n".join("command: " + c for c in CHECKED))
    for p in problems:
        print(p)
    print(f"{len(scanned)} files checked, {len(problems)} broken references")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
