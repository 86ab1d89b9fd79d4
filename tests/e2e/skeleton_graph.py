#!/usr/bin/python3
"""Independent reader of skeleton files (.ply ascii with element edge, .obj l lines,
.cg e lines) for the end-to-end tests: prints a file's topology, checks it against
expectations, or checks that two files hold the same graph.

  skeleton_graph.py show FILE
  skeleton_graph.py check FILE [--cycles N] [--max-cycles N] [--cycles-as OTHER_FILE]
                               [--components N] [--tips N] [--min-tips N] [--junctions N]
                               [--min-nodes N]
  skeleton_graph.py same FILE_A FILE_B
"""
import argparse
import sys


def read(path):
    lines = open(path).read().splitlines()
    nodes, edges = [], []
    if path.endswith(".ply"):
        end = lines.index("end_header")
        counts = {l.split()[1]: int(l.split()[2]) for l in lines[:end] if l.startswith("element")}
        order = [l.split()[1] for l in lines[:end] if l.startswith("element")]
        row = end + 1
        for element in order:
            for l in lines[row:row + counts[element]]:
                fields = l.split()
                if element == "vertex":
                    nodes.append(tuple(float(x) for x in fields[:3]))
                elif element == "edge":
                    edges.append((int(fields[0]), int(fields[1])))
            row += counts[element]
    else:
        keyword = "l" if path.endswith(".obj") else "e"
        for l in lines:
            fields = l.split()
            if fields and fields[0] == "v":
                nodes.append(tuple(float(x) for x in fields[1:4]))
            elif fields and fields[0] == keyword:
                ids = [int(x) - 1 for x in fields[1:]]
                edges += list(zip(ids, ids[1:]))
    edges = sorted({(min(a, b), max(a, b)) for a, b in edges if a != b})
    return nodes, edges


def topology(nodes, edges):
    parent = list(range(len(nodes)))

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for a, b in edges:
        parent[find(a)] = find(b)
    components = len({find(i) for i in range(len(nodes))})
    degree = [0] * len(nodes)
    for a, b in edges:
        degree[a] += 1
        degree[b] += 1
    return {
        "nodes": len(nodes), "edges": len(edges), "components": components,
        "cycles": len(edges) - len(nodes) + components,
        "tips": degree.count(1), "junctions": sum(d >= 3 for d in degree),
    }


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("command", choices=["show", "check", "same"])
    parser.add_argument("files", nargs="+")
    for name in ["cycles", "max-cycles", "components", "tips", "min-tips", "junctions", "min-nodes"]:
        parser.add_argument("--" + name, type=int)
    parser.add_argument("--cycles-as", help="expect as many cycles as this other skeleton file has")
    args = parser.parse_args()

    if args.command == "same":
        (na, ea), (nb, eb) = read(args.files[0]), read(args.files[1])
        worst = max((max(abs(x - y) for x, y in zip(p, q)) for p, q in zip(na, nb)), default=0.0)
        if len(na) != len(nb) or ea != eb or worst > 1e-4:
            sys.exit(f"FAIL: {args.files[0]} and {args.files[1]} differ "
                     f"({len(na)} vs {len(nb)} nodes, edges equal: {ea == eb}, largest coordinate gap {worst:g})")
        print(f"same graph: {args.files[0]} = {args.files[1]} ({len(na)} nodes, {len(ea)} edges)")
        return

    t = topology(*read(args.files[0]))
    print(args.files[0], t)
    if args.command == "show":
        return
    failures = []
    for key in ["cycles", "components", "tips", "junctions"]:
        wanted = getattr(args, key)
        if wanted is not None and t[key] != wanted:
            failures.append(f"{key} = {t[key]}, expected {wanted}")
    if args.max_cycles is not None and t["cycles"] > args.max_cycles:
        failures.append(f"cycles = {t['cycles']}, expected at most {args.max_cycles}")
    if args.cycles_as is not None:
        other = topology(*read(args.cycles_as))["cycles"]
        if t["cycles"] != other:
            failures.append(f"cycles = {t['cycles']}, expected {other} as in {args.cycles_as}")
    if args.min_tips is not None and t["tips"] < args.min_tips:
        failures.append(f"tips = {t['tips']}, expected at least {args.min_tips}")
    if args.min_nodes is not None and t["nodes"] < args.min_nodes:
        failures.append(f"nodes = {t['nodes']}, expected at least {args.min_nodes}")
    if failures:
        sys.exit(f"FAIL: {args.files[0]}: " + "; ".join(failures))


if __name__ == "__main__":
    main()
