#!/usr/bin/env python3
"""Check that include/quat keeps its layers, and print its deepest include chain.

The layers (docs/architecture.md), each allowed to include the ones listed for it and nothing
above: detail/ is the foundation and includes no public header; the rotation headers at the top
of include/quat build on it; each family folder (with its own detail/) builds on those and on the
families named below. Umbrella headers (quat.hpp, <family>.hpp) and the old include paths that
forward to a family's header may include anything.

    python3 tools/check_layers.py          check, and print the deepest chain; exit 1 on a violation
"""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from amalgamate import includes_of, only_includes  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
QUAT = ROOT / "include" / "quat"

# What each layer may include besides itself.
MAY_INCLUDE = {
    "detail": set(),
    "core": {"detail"},
    "rigid": {"detail", "core"},
    "fitting": {"detail", "core"},
    "lie": {"detail", "core", "rigid", "fitting"},
    "paths": {"detail", "core", "lie"},
    "batch": {"detail", "core", "rigid", "paths"},
    "registration": {"detail", "core", "rigid", "fitting", "lie"},
    "trajectory": {"detail", "core", "rigid", "fitting", "lie", "paths"},
    "io": {"detail", "core"},
    "interop": {"detail", "core", "rigid", "fitting", "lie", "paths", "batch", "registration",
                "io", "trajectory"},
}


def layer_of(path: Path) -> str:
    parts = path.relative_to(QUAT).parts
    if parts == ("config.hpp",):
        return "config"  # the version and QUAT_ASSERT: below everything, detail/ included
    if len(parts) == 1:
        if only_includes(path):
            return "entry"
        return "io" if parts[0] == "io.hpp" else "core"
    return parts[0]  # detail, or a family folder (its detail/ belongs to it)


def main() -> int:
    headers = sorted(p.resolve() for p in QUAT.rglob("*.hpp"))
    graph = {h: includes_of(h) for h in headers}
    problems = []
    for header, targets in graph.items():
        layer = layer_of(header)
        if layer in ("entry", "config"):
            continue
        if layer not in MAY_INCLUDE:
            problems.append(f"{header.relative_to(QUAT)}: in no layer (add it to MAY_INCLUDE)")
            continue
        for target in targets:
            other = layer_of(target)
            if other not in (layer, "config") and other not in MAY_INCLUDE[layer]:
                problems.append(f"{header.relative_to(QUAT)} ({layer}) includes "
                                f"{target.relative_to(QUAT)} ({other})")
    longest = {}

    def chain(header):
        if header not in longest:
            longest[header] = [header]
            for target in graph[header]:
                candidate = [header] + chain(target)
                if len(candidate) > len(longest[header]):
                    longest[header] = candidate
        return longest[header]

    deepest = max((chain(h) for h in headers), key=len)
    print(f"deepest include chain: {len(deepest)} headers: "
          + " -> ".join(str(h.relative_to(QUAT)) for h in deepest))
    for problem in problems:
        print("layer violation:", problem)
    print(f"{len(headers)} headers, {sum(map(len, graph.values()))} includes, "
          f"{len(problems)} layer violations")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
