"""Sampled test shapes with known skeletons (numpy only)."""
import numpy as np


def torus(count=4000, major=1.0, minor=0.25, seed=1):
    """A torus sampled on its surface: one cycle."""
    rng = np.random.default_rng(seed)
    t, u = rng.uniform(0, 2 * np.pi, count), rng.uniform(0, 2 * np.pi, count)
    ring = major + minor * np.cos(u)
    return np.stack([ring * np.cos(t), ring * np.sin(t), minor * np.sin(u)], axis=1)


def tube(start, end, radius, count, rng):
    """The side of a cylinder from start to end."""
    start, end = np.asarray(start, float), np.asarray(end, float)
    axis = end - start
    length = np.linalg.norm(axis)
    axis /= length
    helper = np.array([0.0, 0.0, 1.0]) if abs(axis[2]) < 0.9 else np.array([1.0, 0.0, 0.0])
    u = np.cross(axis, helper)
    u /= np.linalg.norm(u)
    v = np.cross(axis, u)
    s, a = rng.uniform(0, length, count), rng.uniform(0, 2 * np.pi, count)
    return start + s[:, None] * axis + radius * (np.cos(a)[:, None] * u + np.sin(a)[:, None] * v)


def y_shape(count=4500, radius=0.08, seed=2):
    """Three tubes from a common centre, 120 degrees apart: three tips, one junction."""
    rng = np.random.default_rng(seed)
    arms = [tube([0, 0, 0], [np.cos(a), np.sin(a), 0], radius, count // 3, rng)
            for a in (np.pi / 2, np.pi / 2 + 2 * np.pi / 3, np.pi / 2 + 4 * np.pi / 3)]
    return np.concatenate(arms)


def plate_with_two_holes(count=6000, seed=5):
    """A square plate 1.6 wide, one layer of points, with two round holes: two cycles."""
    rng = np.random.default_rng(seed)
    points = rng.uniform(0, 1.6, (3 * count, 2))
    outside = (np.hypot(points[:, 0] - 0.45, points[:, 1] - 0.8) > 0.25) & \
              (np.hypot(points[:, 0] - 1.15, points[:, 1] - 0.8) > 0.25)
    points = points[outside][:count]
    return np.concatenate([points, np.zeros((len(points), 1))], axis=1)
