#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
"""Checks the module dependencies of the source tree against one table.

    check_dependencies.py --root SOURCE_DIR --table dependencies.txt [--links module_links.txt]
    check_dependencies.py --self-test

The table (tests/architecture/dependencies.txt) names each module, its CMake
target, the files it owns and the modules it may use. The check fails, naming
file, line and include, when
  (a) a file includes a header of a module its module may not use (an upward
      or sideways include), or an internal header (outside include/) of another
      module that the table does not open to it;
  (b) the includes between modules form a cycle, or the table does;
  (c) a module's target links (directly) a tessella target of a module it does
      not include, or does not link one it includes (--links: written by CMake
      at configure time, "target: linked tessella targets" per line).
Only the Python standard library is used.
"""

import argparse
import os
import re
import sys
import tempfile
import unittest

SOURCE_SUFFIXES = (".hpp", ".cpp", ".ipp", ".h")
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')


def logical_lines(text):
    """(first line number, line) pairs, a line ending in a backslash joined with the next."""
    pending, start = "", 0
    for number, line in enumerate(text.splitlines(), 1):
        if not pending:
            start = number
        stripped = line.split("#", 1)[0].rstrip()
        if stripped.endswith("\\"):
            pending += stripped[:-1] + " "
            continue
        yield start, pending + line
        pending = ""
    if pending:
        yield start, pending


class Table:
    """The parsed dependency table: modules in order, with target, file prefixes and allowed uses."""

    def __init__(self, text, where="the table"):
        self.order = []
        self.target = {}
        self.prefixes = {}
        self.uses = {}
        self.internal = {}
        self.errors = []
        for number, line in logical_lines(text):
            words = line.split("#", 1)[0].split()
            if not words:
                continue
            if len(words) < 4:
                self.errors.append(f"{where}:{number}: expected 'module target files uses...', got '{line.strip()}'")
                continue
            name, target, files, uses = words[0], words[1], words[2], words[3:]
            if name in self.target:
                self.errors.append(f"{where}:{number}: module {name} is listed twice")
                continue
            self.order.append(name)
            self.target[name] = None if target == "-" else target
            self.prefixes[name] = files.split(",")
            self.uses[name] = {u for u in uses if u != "-" and not u.startswith("internal:")}
            self.internal[name] = {u[len("internal:"):] for u in uses if u.startswith("internal:")}
        for name in self.order:
            for used in sorted(self.uses[name] | self.internal[name]):
                if used not in self.target:
                    self.errors.append(f"{where}: module {name} uses {used}, which is not in the table")

    def owner(self, path):
        """The module owning a path relative to the root (longest matching prefix), or None."""
        best, best_length = None, -1
        for name in self.order:
            for prefix in self.prefixes[name]:
                matches = path == prefix or (prefix.endswith("/") and path.startswith(prefix))
                if matches and len(prefix) > best_length:
                    best, best_length = name, len(prefix)
        return best


def cycles(graph):
    """The strongly connected components of more than one node (or with a self edge), each as a sorted list."""
    index, low, stack, on_stack, found = {}, {}, [], set(), []
    counter = [0]

    def visit(node):
        index[node] = low[node] = counter[0]
        counter[0] += 1
        stack.append(node)
        on_stack.add(node)
        for successor in sorted(graph.get(node, ())):
            if successor not in index:
                visit(successor)
                low[node] = min(low[node], low[successor])
            elif successor in on_stack:
                low[node] = min(low[node], index[successor])
        if low[node] == index[node]:
            component = []
            while True:
                member = stack.pop()
                on_stack.discard(member)
                component.append(member)
                if member == node:
                    break
            if len(component) > 1 or node in graph.get(node, ()):
                found.append(sorted(component))

    for node in sorted(graph):
        if node not in index:
            visit(node)
    return found


def cycle_path(graph, members):
    """One closed walk through a cycle's members, e.g. 'io -> mesh -> io'."""
    start = members[0]
    path, node, seen = [start], start, {start}
    while True:
        successors = sorted(s for s in graph[node] if s in members)
        nxt = next((s for s in successors if s == start and len(path) > 1), None) or \
            next((s for s in successors if s not in seen), successors[0])
        path.append(nxt)
        if nxt in seen:
            return " -> ".join(path[path.index(nxt):])
        seen.add(nxt)
        node = nxt


def is_public(path):
    """Headers under a module's include/ directory are its public ones."""
    return "/include/" in "/" + path


def source_files(root, table):
    """Every C++ file the table assigns to a module: {relative path: module}."""
    owned = {}
    for name in table.order:
        for prefix in table.prefixes[name]:
            top = os.path.join(root, prefix)
            if os.path.isfile(top):
                candidates = [prefix]
            elif os.path.isdir(top):
                candidates = []
                for directory, subdirectories, files in os.walk(top):
                    subdirectories.sort()
                    for file in sorted(files):
                        if file.endswith(SOURCE_SUFFIXES):
                            candidates.append(os.path.relpath(os.path.join(directory, file), root))
            else:
                continue
            for path in candidates:
                path = path.replace(os.sep, "/")
                if table.owner(path) == name:
                    owned[path] = name
    return owned


def include_roots(owned):
    """Directories that hold public headers, as relative paths ending in include/."""
    roots = set()
    for path in owned:
        if "/include/" in "/" + path:
            roots.add(path[: ("/" + path).index("/include/") + len("include/")])
    return sorted(roots)


def resolve(root, including, name, roots):
    """The relative path of the file an include names, or None for one outside the tree."""
    candidates = [os.path.normpath(os.path.join(os.path.dirname(including), name))]
    candidates += [os.path.normpath(os.path.join(r, name)) for r in roots]
    for candidate in candidates:
        if not candidate.startswith("..") and os.path.isfile(os.path.join(root, candidate)):
            return candidate.replace(os.sep, "/")
    return None


def check(root, table, links=None):
    """All violations, as messages; empty when the tree keeps to the table."""
    problems = list(table.errors)
    table_graph = {name: set(table.uses[name]) for name in table.order}
    for members in cycles(table_graph):
        problems.append(f"the table's uses form a cycle: {cycle_path(table_graph, members)}")

    owned = source_files(root, table)
    roots = include_roots(owned)
    includes = {name: {} for name in table.order}  # module -> {included module: first "file:line"}
    for path, module in sorted(owned.items()):
        with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
            lines = f.read().splitlines()
        for number, line in enumerate(lines, 1):
            match = INCLUDE.match(line)
            if not match:
                continue
            name = match.group(2)
            target = resolve(root, path, name, roots)
            if target is None:
                if name.startswith("tessella/"):
                    problems.append(f"{path}:{number}: #include \"{name}\" names no header of any module")
                continue  # a system or third-party header
            used = table.owner(target)
            if used is None or used == module:
                continue
            where = f"{path}:{number}"
            includes[module].setdefault(used, where)
            if not is_public(target):
                if used not in table.internal[module]:
                    problems.append(f"{where}: {module} includes {target}, an internal header of {used}")
            elif used not in table.uses[module]:
                problems.append(f"{where}: {module} may not include {name}: {used} is not among the modules "
                                f"{module} uses ({', '.join(sorted(table.uses[module])) or 'none'}; "
                                f"tests/architecture/dependencies.txt)")

    include_graph = {m: set(used) for m, used in includes.items()}
    for members in cycles(include_graph):
        path = cycle_path(include_graph, members)
        steps = path.split(" -> ")
        evidence = ", ".join(f"{a} -> {b} at {includes[a][b]}" for a, b in zip(steps, steps[1:]))
        problems.append(f"the modules include each other in a cycle: {path} ({evidence})")

    if links is not None:
        module_of_target = {t: m for m, t in table.target.items() if t}
        for module in table.order:
            target = table.target[module]
            if not target or target not in links:
                continue  # no target, or not built in this configuration
            linked = {module_of_target[t] for t in links[target] if t in module_of_target} - {module}
            included = set(includes[module])
            for extra in sorted(linked - included):
                problems.append(f"{target} links {table.target[extra]}, but no file of {module} includes a header "
                                f"of {extra}: link only what you include")
            for missing in sorted(included - linked):
                if table.target[missing] is None:
                    continue
                problems.append(f"{module} includes {missing} ({includes[module][missing]}) but {target} does not "
                                f"link {table.target[missing]}: link what you include")
    return problems


def read_links(path):
    links = {}
    with open(path, encoding="utf-8") as f:
        for line in f:
            if ":" in line:
                target, linked = line.split(":", 1)
                links[target.strip()] = set(linked.split())
    return links


class SelfTest(unittest.TestCase):
    """The check on small made-up trees: it passes a clean one and names each kind of violation."""

    TABLE = """
        low    low_lib    low/    -
        part   part_lib   mid/include/x/mid/part.hpp -
        mid    mid_lib    mid/    low part
        top    top_lib    top/    low mid
        tests  -          tests/  mid internal:mid
    """

    def tree(self, files):
        directory = tempfile.TemporaryDirectory()
        self.addCleanup(directory.cleanup)
        for path, text in files.items():
            full = os.path.join(directory.name, path)
            os.makedirs(os.path.dirname(full), exist_ok=True)
            with open(full, "w", encoding="utf-8") as f:
                f.write(text)
        return directory.name

    def clean_files(self):
        return {
            "low/include/x/low/a.hpp": "#pragma once\n#include <vector>\n",
            "low/src/a.cpp": '#include "x/low/a.hpp"\n#include "helper.hpp"\n',
            "low/src/helper.hpp": "#pragma once\n",
            "mid/include/x/mid/part.hpp": "#pragma once\n",
            "mid/include/x/mid/b.hpp": '#pragma once\n#include "x/low/a.hpp"\n#include "x/mid/part.hpp"\n',
            "mid/src/b.cpp": '#include "x/mid/b.hpp"\n#include "inner.hpp"\n',
            "mid/src/inner.hpp": "#pragma once\n",
            "top/src/c.cpp": '#include "x/mid/b.hpp"\n#include "x/low/a.hpp"\n',
            "tests/t.cpp": '#include "x/mid/b.hpp"\n#include "../mid/src/inner.hpp"\n',
        }

    LINKS = {"low_lib": set(), "mid_lib": {"low_lib", "part_lib"}, "top_lib": {"low_lib", "mid_lib"}}

    def run_check(self, files, links=None):
        return check(self.tree(files), Table(self.TABLE), links if links is not None else self.LINKS)

    def test_a_clean_tree_passes(self):
        self.assertEqual(self.run_check(self.clean_files()), [])

    def test_an_upward_include_fails(self):
        files = self.clean_files()
        files["low/src/a.cpp"] += '#include "x/mid/b.hpp"\n'
        problems = self.run_check(files, dict(self.LINKS, low_lib={"mid_lib"}))
        self.assertTrue(any("low/src/a.cpp:3: low may not include x/mid/b.hpp" in p for p in problems), problems)
        self.assertTrue(any("cycle: low -> mid -> low" in p for p in problems), problems)

    def test_a_sideways_include_of_a_part_fails(self):
        files = self.clean_files()
        files["low/src/a.cpp"] += '#include "x/mid/part.hpp"\n'
        problems = self.run_check(files)
        self.assertTrue(any("low may not include x/mid/part.hpp: part is not among" in p for p in problems), problems)

    def test_an_internal_header_of_another_module_fails(self):
        files = self.clean_files()
        files["top/src/c.cpp"] += '#include "../../mid/src/inner.hpp"\n'
        problems = self.run_check(files)
        self.assertEqual(problems, ["top/src/c.cpp:3: top includes mid/src/inner.hpp, an internal header of mid"])

    def test_an_unknown_tessella_header_fails(self):
        files = self.clean_files()
        files["top/src/c.cpp"] += '#include "tessella/nowhere.hpp"\n'
        self.assertEqual(self.run_check(files), ['top/src/c.cpp:3: #include "tessella/nowhere.hpp" names no header '
                                                 'of any module'])

    def test_linking_a_module_not_included_fails(self):
        problems = self.run_check(self.clean_files(), dict(self.LINKS, low_lib={"part_lib"}))
        self.assertEqual(problems, ["low_lib links part_lib, but no file of low includes a header of part: "
                                    "link only what you include"])

    def test_including_a_module_not_linked_fails(self):
        problems = self.run_check(self.clean_files(), dict(self.LINKS, top_lib={"mid_lib"}))
        self.assertEqual(len(problems), 1)
        self.assertIn("top includes low (top/src/c.cpp:2) but top_lib does not link low_lib", problems[0])

    def test_a_line_ending_in_a_backslash_goes_on(self):
        table = Table("top top_lib top/ low \\\n    mid  # more uses\nlow low_lib low/ -\nmid mid_lib mid/ low\n")
        self.assertEqual(table.errors, [])
        self.assertEqual(table.uses["top"], {"low", "mid"})
        self.assertEqual(table.order, ["top", "low", "mid"])

    def test_a_cycle_in_the_table_fails(self):
        table = Table(self.TABLE.replace("low    low_lib    low/    -", "low    low_lib    low/    top"))
        problems = check(self.tree(self.clean_files()), table, self.LINKS)
        self.assertTrue(any("the table's uses form a cycle: low -> top -> low" in p for p in problems), problems)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--root", help="the source tree")
    parser.add_argument("--table", help="the dependency table (tests/architecture/dependencies.txt)")
    parser.add_argument("--links", help="the targets' direct tessella links, written by CMake")
    parser.add_argument("--self-test", action="store_true", help="check the checker on made-up trees")
    args = parser.parse_args()
    if args.self_test:
        suite = unittest.defaultTestLoader.loadTestsFromTestCase(SelfTest)
        return 0 if unittest.TextTestRunner(verbosity=2).run(suite).wasSuccessful() else 1
    if not args.root or not args.table:
        parser.error("--root and --table are required (or --self-test)")
    with open(args.table, encoding="utf-8") as f:
        table = Table(f.read(), os.path.relpath(args.table, args.root))
    problems = check(args.root, table, read_links(args.links) if args.links else None)
    for problem in problems:
        print(problem)
    modules = ", ".join(table.order)
    if problems:
        print(f"{len(problems)} dependency problem(s) (modules: {modules})")
        return 1
    print(f"dependencies ok: every include points to an allowed module, no cycles"
          f"{', every target links what it includes' if args.links else ''} (modules: {modules})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
