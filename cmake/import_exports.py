#!/usr/bin/env python3
"""The public names c2f/c2f.hpp declares, as the using-declarations of modules/umbrella/src/c2f.cppm.

Usage: cmake/import_exports.py SOURCE_DIR            prints the names, one per line (ns::name)
       cmake/import_exports.py SOURCE_DIR --check    exits 1 naming every public name the module
                                                     does not export, or exports but no header has

A name is public when a header included by c2f/c2f.hpp declares it at namespace scope in c2f or
c2f::vision (not detail): classes, structs, enums, concepts, aliases, constants and functions.
"""
import glob
import os
import re
import sys


def public_names(source):
    umbrella = os.path.join(source, "modules/umbrella/include/c2f/c2f.hpp")
    headers = re.findall(r'#include "(c2f/.*)"', open(umbrella).read())
    roots = glob.glob(os.path.join(source, "modules/**/include"), recursive=True) + glob.glob(
        os.path.join(source, "adapters/**/include"), recursive=True)
    names = set()
    for header in headers:
        path = next(os.path.join(r, header) for r in roots if os.path.exists(os.path.join(r, header)))
        text = re.sub(r"//(?! namespace).*", "", open(path).read())
        stack = []  # (namespace, brace depth inside it)
        depth = 0
        for line in text.splitlines():
            opened = re.match(r"namespace ([\w:]+) \{", line)
            at_namespace_scope = bool(stack) and depth == stack[-1][1]
            if opened:
                depth += 1
                stack.append((opened.group(1), depth))
                continue
            depth += line.count("{") - line.count("}")
            while stack and depth < stack[-1][1]:
                stack.pop()
            namespace = "::".join(name for name, _ in stack)
            if not at_namespace_scope or "detail" in namespace or line[:1] in (" ", "\t", "#", "}", ""):
                continue
            patterns = [
                r"(?:template\s*<.*>\s*)?(?:class|struct|enum class|enum|union)\s+(\w+)(?!\s*;)",
                r"concept\s+(\w+)",
                r"(?:inline\s+)?(?:constexpr\s+)?using\s+(\w+)\s*=",
                r"(?:inline\s+)?constexpr\s+[\w:<>, *]+\s+(\w+)\s*[{=\[]",
                r"(?:\[\[nodiscard\]\]\s*)?(?:inline\s+|constexpr\s+|static\s+)*[\w:<>,\s\*&]+?[\s\*&](\w+)\s*\(",
                r"(?:\[\[nodiscard\]\]\s*)?(?:inline\s+|constexpr\s+)*decltype\(auto\)\s+(\w+)\s*\(",
            ]
            for pattern in patterns:
                found = re.match(pattern, line)
                if found and found.group(1) not in ("if", "for", "while", "switch", "return"):
                    names.add(namespace + "::" + found.group(1))
                    break
    return names


def main():
    source = sys.argv[1]
    names = public_names(source)
    if "--check" not in sys.argv:
        print("\n".join(sorted(names)))
        return 0
    module = open(os.path.join(source, "modules/umbrella/src/c2f.cppm")).read()
    exported = set(re.findall(r"^using ([\w:]+);", module, re.M))
    missing, stale = sorted(names - exported), sorted(exported - names)
    for name in missing:
        print(f"c2f.cppm does not export {name}")
    for name in stale:
        print(f"c2f.cppm exports {name}, which no public header declares")
    print(f"{len(exported)} names exported, {len(missing)} missing, {len(stale)} stale")
    return 1 if missing or stale else 0


if __name__ == "__main__":
    sys.exit(main())
