#!/usr/bin/python3
"""Renders point clouds and skeletons (ASCII PLY, OFF or XYZ) side by side into a PNG.

usage: render_points.py [--view ELEVATION,AZIMUTH] OUT.png TITLE FILE[:LABEL] [FILE[:LABEL] ...]
Each file gets its own panel, all seen from the same viewpoint (degrees; 20,-60 unless
given) and scale; the first
file is drawn faintly behind the others so that they can be compared with it. A PLY
file with an edge element is drawn as a skeleton: its edges as lines, nodes as dots;
inferred bones (the edge property `inferred` 1: a gap in the data bridged) dashed magenta,
as the Edit Skeleton tool draws them.
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_edges(path):
    """The (a, b, inferred) triples of an ASCII PLY's edge element (elements in file order;
    inferred False where the file has no such property)."""
    with open(path, "r", errors="replace") as f:
        lines = f.read().splitlines()
    if not lines or lines[0].strip() != "ply":
        return []
    end = lines.index("end_header")
    elements = []  # (name, count, property names)
    for line in lines[:end]:
        words = line.split()
        if words[:1] == ["element"]:
            elements.append((words[1], int(words[2]), []))
        elif words[:1] == ["property"] and elements:
            elements[-1][2].append(words[-1])
    row = end + 1
    for name, count, properties in elements:
        if name == "edge":
            flag = properties.index("inferred") if "inferred" in properties else None
            edges = []
            for line in lines[row:row + count]:
                values = [int(v) for v in line.split()]
                edges.append((values[0], values[1], flag is not None and values[flag] == 1))
            return edges
        row += count
    return []


def read_points(path):
    with open(path, "r", errors="replace") as f:
        lines = f.read().splitlines()
    if lines and lines[0].strip() == "ply":
        count, start = 0, 0
        for i, line in enumerate(lines):
            words = line.split()
            if words[:2] == ["element", "vertex"]:
                count = int(words[2])
            if line.strip() == "end_header":
                start = i + 1
                break
        rows = lines[start:start + count]
    elif lines and lines[0].strip().endswith("OFF"):
        body = [l for l in lines[1:] if l.strip() and not l.startswith("#")]
        count = int(body[0].split()[0])
        rows = body[1:1 + count]
    else:
        rows = [l for l in lines if l.strip() and not l.startswith("#")]
    return np.array([[float(v) for v in r.split()[:3]] for r in rows])


def main():
    arguments = sys.argv[1:]
    elevation, azimuth = 20.0, -60.0
    if arguments and arguments[0] == "--view":
        elevation, azimuth = (float(v) for v in arguments[1].split(","))
        arguments = arguments[2:]
    out, title, inputs = arguments[0], arguments[1], arguments[2:]
    clouds = []
    for item in inputs:
        path, _, label = item.partition(":")
        clouds.append((read_points(path), label or path, read_edges(path)))
    everything = np.vstack([c for c, _, _ in clouds])
    lo, hi = everything.min(axis=0), everything.max(axis=0)
    centre, half = (lo + hi) / 2, (hi - lo).max() / 2
    fig = plt.figure(figsize=(5 * len(clouds), 5.4), dpi=110)
    fig.suptitle(title)
    for i, (points, label, edges) in enumerate(clouds):
        ax = fig.add_subplot(1, len(clouds), i + 1, projection="3d")
        if i == 0:
            ax.scatter(*points.T, s=1.5, c=points[:, 2], cmap="viridis", depthshade=True)
        else:
            reference = clouds[0][0]
            ax.scatter(*reference.T, s=0.5, c="lightgray", alpha=0.25, depthshade=False)
            if edges:
                for a, b, inferred in edges:
                    if inferred:
                        ax.plot(*points[[a, b]].T, color="magenta", linewidth=2, linestyle="--")
                    else:
                        ax.plot(*points[[a, b]].T, color="crimson", linewidth=2)
                ax.scatter(*points.T, s=8, c="black", depthshade=False)
            else:
                ax.scatter(*points.T, s=2.5, c="crimson", depthshade=False)
        for axis, c in zip("xyz", centre):
            getattr(ax, f"set_{axis}lim")(c - half, c + half)
        ax.set_box_aspect((1, 1, 1))
        ax.view_init(elev=elevation, azim=azimuth)
        ax.set_axis_off()
        count = f"{len(points)} nodes, {len(edges)} edges" if edges else f"{len(points)} points"
        inferred = sum(1 for edge in edges if edge[2])
        if inferred:
            count += f" ({inferred} inferred, dashed)"
        ax.set_title(f"{label}\n{count}")
    fig.tight_layout(rect=(0, 0, 1, 0.93))
    fig.savefig(out)


if __name__ == "__main__":
    main()
