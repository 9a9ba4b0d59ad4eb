#!/usr/bin/env python3
"""Independent check of Flapwright's URDF export against its trajectory file.

Usage: check_urdf.py URDF TRAJECTORY [--fk-tol M] [--inertia-rtol R] [--readers LIST]

Two readers that share no code with the Rust exporter, or with each other, read the URDF:
yourdfpy (lxml parser, trimesh meshes and scene graph) and pybullet (Bullet's own URDF
importer and multibody forward kinematics). For each reader:

  load      the file loads with every mesh (mesh filenames are relative to the URDF);
  links     every link that is the child of a non-fixed joint has visual and collision
            geometry, mass > 0 and a valid inertia (symmetric, positive definite, principal
            moments satisfying the triangle inequality within --inertia-rtol);
  fk        for every trajectory sample, the joint values are set, forward kinematics
            maps every key point from its link frame to the base link frame, and the
            largest distance to key_points_ac_m must not exceed --fk-tol (1e-6 m).

A last check compares the two readers' masses and principal moments of inertia.
Prints a compact summary and exits 1 on any failure, 0 when everything passes (2 for bad
command-line usage). The last line reads "urdf-check: N passed, N failed".
All arithmetic is numpy float64.
"""

from __future__ import annotations

import argparse
import contextlib
import ctypes
import json
import logging
import math
import os
import sys
import tempfile
from dataclasses import dataclass, field

import numpy as np

FK_TOL_M = 1e-6
INERTIA_RTOL = 1e-6
# An STL whose extent exceeds this is not in metres (a millimetre file of a 0.3 m part
# spans 300 "metres"); no part of an aircraft wing is this large.
MAX_MESH_EXTENT_M = 200.0
MAX_REASONS_SHOWN = 40


# ---------------------------------------------------------------------------------------
# Shared helpers
# ---------------------------------------------------------------------------------------


@dataclass
class Trajectory:
    joint_names: list
    key_points: list  # (name, link, position_link (3,))
    samples: list  # (joint_values (n,), {name: (3,)})
    problems: list = field(default_factory=list)


def load_trajectory(path: str) -> Trajectory:
    with open(path, encoding="utf-8") as f:
        data = json.load(f)
    problems = []
    joint_names = [str(n) for n in data.get("joint_names", [])]
    if len(set(joint_names)) != len(joint_names):
        problems.append("joint_names has duplicates")
    key_points = []
    for kp in data.get("key_points", []):
        pos = np.asarray(kp["position_link_m"], dtype=np.float64)
        if pos.shape != (3,) or not np.all(np.isfinite(pos)):
            problems.append(f"key point {kp.get('name')}: position_link_m is not 3 finite numbers")
            continue
        key_points.append((str(kp["name"]), str(kp["link"]), pos))
    names = [k[0] for k in key_points]
    if len(set(names)) != len(names):
        problems.append("key_points has duplicate names")
    samples = []
    for i, s in enumerate(data.get("samples", [])):
        q = np.asarray(s.get("joint_values", []), dtype=np.float64)
        if q.shape != (len(joint_names),) or not np.all(np.isfinite(q)):
            problems.append(
                f"sample {i}: {q.size} joint values for {len(joint_names)} joints (or not finite)"
            )
            continue
        pts = {}
        given = s.get("key_points_ac_m", {})
        missing = [n for n in names if n not in given]
        if missing:
            problems.append(f"sample {i}: key points missing from key_points_ac_m: {', '.join(missing[:5])}")
        for n in names:
            if n in given:
                p = np.asarray(given[n], dtype=np.float64)
                if p.shape != (3,) or not np.all(np.isfinite(p)):
                    problems.append(f"sample {i}: key point {n} is not 3 finite numbers")
                    continue
                pts[n] = p
        samples.append((q, pts))
    if not joint_names:
        problems.append("no joint_names")
    if not key_points:
        problems.append("no key_points")
    if not samples:
        problems.append("no samples")
    return Trajectory(joint_names, key_points, samples, problems)


def inertia_problems(mass, tensor, rtol: float) -> list:
    """Why (mass, 3x3 inertia tensor) is not physical; [] when it is."""
    out = []
    if mass is None:
        out.append("no mass")
    elif not math.isfinite(mass) or mass <= 0.0:
        out.append(f"mass {mass:g} (must be > 0)")
    if tensor is None:
        out.append("no inertia")
        return out
    inertia = np.asarray(tensor, dtype=np.float64)
    if inertia.shape != (3, 3) or not np.all(np.isfinite(inertia)):
        out.append("inertia is not a finite 3x3 matrix")
        return out
    scale = float(np.max(np.abs(inertia)))
    if scale == 0.0:
        out.append("inertia is zero")
        return out
    if np.max(np.abs(inertia - inertia.T)) > rtol * scale:
        out.append("inertia is not symmetric")
    moments = np.sort(np.linalg.eigvalsh(0.5 * (inertia + inertia.T)))
    if moments[0] <= rtol * scale:
        out.append("inertia not positive definite (principal moments " + fmt_vec(moments) + ")")
    elif moments[0] + moments[1] < moments[2] * (1.0 - rtol):
        out.append(
            "principal moments " + fmt_vec(moments) + " break the triangle inequality "
            f"({moments[0]:.6g} + {moments[1]:.6g} < {moments[2]:.6g})"
        )
    return out


def fmt_vec(v) -> str:
    return "(" + ", ".join(f"{x:.6g}" for x in v) + ")"


def quat_to_matrix(q) -> np.ndarray:
    """Rotation matrix of a quaternion given as (x, y, z, w), renormalised."""
    x, y, z, w = np.asarray(q, dtype=np.float64) / np.linalg.norm(np.asarray(q, dtype=np.float64))
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ],
        dtype=np.float64,
    )


def pose(position, quaternion) -> np.ndarray:
    t = np.eye(4, dtype=np.float64)
    t[:3, :3] = quat_to_matrix(quaternion)
    t[:3, 3] = np.asarray(position, dtype=np.float64)
    return t


def rigid_inverse(t: np.ndarray) -> np.ndarray:
    inv = np.eye(4, dtype=np.float64)
    inv[:3, :3] = t[:3, :3].T
    inv[:3, 3] = -t[:3, :3].T @ t[:3, 3]
    return inv


@contextlib.contextmanager
def captured_c_output():
    """Capture what C code writes to file descriptors 1 and 2 (pybullet's printf and
    b3Warning/b3Error); yields a list that receives the text when the block ends."""
    sink: list = []
    sys.stdout.flush()
    sys.stderr.flush()
    libc = ctypes.CDLL(None)
    saved = (os.dup(1), os.dup(2))
    with tempfile.TemporaryFile(mode="w+b") as tmp:
        os.dup2(tmp.fileno(), 1)
        os.dup2(tmp.fileno(), 2)
        try:
            yield sink
        finally:
            libc.fflush(None)
            sys.stdout.flush()
            sys.stderr.flush()
            os.dup2(saved[0], 1)
            os.dup2(saved[1], 2)
            os.close(saved[0])
            os.close(saved[1])
            tmp.seek(0)
            sink.append(tmp.read().decode("utf-8", "replace"))


@dataclass
class ReaderResult:
    name: str
    version: str = "?"
    loaded: bool = False
    load_problems: list = field(default_factory=list)
    n_links: int = 0
    n_joints: int = 0
    n_movable: int = 0
    meshes: str = ""
    link_problems: dict = field(default_factory=dict)  # link -> [reasons]
    movable_links: list = field(default_factory=list)
    fk_problems: list = field(default_factory=list)
    fk_max_err: float = float("nan")
    fk_where: str = ""
    fk_points: int = 0
    inertia: dict = field(default_factory=dict)  # link -> (mass, sorted principal moments)
    notes: list = field(default_factory=list)


def compare_key_points(result: ReaderResult, traj: Trajectory, set_joints, link_from_base_of):
    """Run the trajectory: set_joints(q) poses the model, link_from_base_of(link) returns the
    4x4 pose of a link in the base link frame."""
    worst = -1.0
    count = 0
    for i, (q, expected) in enumerate(traj.samples):
        set_joints(q)
        cache = {}
        for name, link, p_link in traj.key_points:
            if name not in expected:
                continue
            if link not in cache:
                cache[link] = link_from_base_of(link)
            t = cache[link]
            p_base = t[:3, :3] @ p_link + t[:3, 3]
            err = float(np.linalg.norm(p_base - expected[name]))
            if not math.isfinite(err):
                err = float("inf")
            count += 1
            if err > worst:
                worst = err
                result.fk_where = f"sample {i}, key point {name}"
    result.fk_points = count
    result.fk_max_err = worst if count else float("nan")


def common_model_checks(result: ReaderResult, traj: Trajectory, links: set, movable_joints: dict):
    """Trajectory against the model as this reader sees it: movable joints and key point links."""
    names = set(traj.joint_names)
    unknown = [n for n in traj.joint_names if n not in movable_joints]
    if unknown:
        result.fk_problems.append("trajectory joints not movable joints of the URDF: " + ", ".join(unknown))
    left_out = sorted(set(movable_joints) - names)
    if left_out:
        result.fk_problems.append("movable URDF joints missing from the trajectory: " + ", ".join(left_out))
    no_link = sorted({link for _, link, _ in traj.key_points if link not in links})
    if no_link:
        result.fk_problems.append("key point links not in the URDF: " + ", ".join(no_link))


# ---------------------------------------------------------------------------------------
# Reader 1: yourdfpy + trimesh
# ---------------------------------------------------------------------------------------


class _Collect(logging.Handler):
    def __init__(self):
        super().__init__(level=logging.WARNING)
        self.records = []

    def emit(self, record):
        self.records.append(f"{record.name}: {record.getMessage()}")


def check_yourdfpy(urdf_path: str, traj: Trajectory, rtol: float) -> ReaderResult:
    result = ReaderResult("yourdfpy")
    try:
        import trimesh
        import yourdfpy
        from functools import partial
        from importlib.metadata import version

        result.version = f"{version('yourdfpy')}, trimesh {version('trimesh')}"
    except Exception as e:  # noqa: BLE001
        result.load_problems.append(f"cannot import yourdfpy/trimesh: {e}")
        return result

    urdf_dir = os.path.dirname(os.path.abspath(urdf_path))
    collect = _Collect()
    loggers = [logging.getLogger("yourdfpy"), logging.getLogger("trimesh")]
    for lg in loggers:
        lg.addHandler(collect)
        lg.propagate = False
    try:
        # Strictly relative to the URDF's directory: yourdfpy's default handler would also
        # search the parent directories and silently use a mesh found there.
        model = yourdfpy.URDF.load(
            urdf_path,
            build_scene_graph=True,
            load_meshes=True,
            build_collision_scene_graph=True,
            load_collision_meshes=True,
            filename_handler=partial(yourdfpy.filename_handler_relative, dir=urdf_dir),
        )
    except Exception as e:  # noqa: BLE001
        result.load_problems.append(f"load failed: {type(e).__name__}: {e}")
        return result
    finally:
        for lg in loggers:
            lg.removeHandler(collect)
            lg.propagate = True
    # yourdfpy only logs a mesh it cannot find or read and goes on without it.
    result.load_problems += [f"logged: {r}" for r in collect.records]

    robot = model.robot
    result.n_links = len(robot.links)
    result.n_joints = len(robot.joints)
    children = [j.child for j in robot.joints]
    roots = [l.name for l in robot.links if l.name not in children]
    if len(roots) != 1:
        result.load_problems.append(f"{len(roots)} root links ({', '.join(roots)}); a URDF tree has one")
    if len(set(children)) != len(children):
        result.load_problems.append("a link is the child of more than one joint")
    if not model.validate():
        result.load_problems += [f"yourdfpy validate: {e}" for e in model.errors]
    base = model.base_link

    # Meshes: every declared element must have become geometry with triangles, in metres.
    def loaded_geometries(scene, link):
        graph = scene.graph
        geometry_nodes = set(graph.nodes_geometry)
        out = []
        for node in graph.transforms.children.get(link, []):
            if node in geometry_nodes:
                out.append(scene.geometry[graph[node][1]])
        return out

    n_visual_loaded = n_collision_loaded = 0
    declared = {}
    for link in robot.links:
        vis = [v for v in link.visuals if v.geometry is not None]
        col = [c for c in link.collisions if c.geometry is not None]
        got_v = loaded_geometries(model.scene, link.name)
        got_c = loaded_geometries(model.collision_scene, link.name)
        declared[link.name] = (len(vis), len(col), got_v, got_c)
        n_visual_loaded += len(got_v)
        n_collision_loaded += len(got_c)
        if len(got_v) < len(vis):
            result.load_problems.append(f"{link.name}: {len(vis)} visual(s) declared, {len(got_v)} loaded")
        # The collision scene concatenates a link's collisions into one geometry.
        if col and not got_c:
            result.load_problems.append(f"{link.name}: {len(col)} collision(s) declared, none loaded")
        for g in got_v + got_c:
            faces = getattr(g, "faces", None)
            if faces is None or len(faces) == 0:
                result.load_problems.append(f"{link.name}: a loaded geometry has no triangles")
                continue
            extent = float(np.max(g.extents))
            if not math.isfinite(extent) or extent > MAX_MESH_EXTENT_M:
                result.load_problems.append(
                    f"{link.name}: mesh extent {extent:g} m (> {MAX_MESH_EXTENT_M:g} m: not metres?)"
                )
    n_mesh_elems = sum(
        1 for l in robot.links for e in l.visuals + l.collisions if e.geometry is not None and e.geometry.mesh is not None
    )
    result.meshes = f"{n_mesh_elems} mesh element(s); {n_visual_loaded} visual, {n_collision_loaded} collision geometries loaded"
    result.loaded = not result.load_problems

    # Movable links: geometry, mass, inertia.
    movable = {j.name: j for j in robot.joints if j.type != "fixed"}
    result.n_movable = len(movable)
    for joint in movable.values():
        link = model.link_map[joint.child]
        result.movable_links.append(link.name)
        n_vis, n_col, got_v, got_c = declared[link.name]
        reasons = []
        if n_vis == 0:
            reasons.append("no visual")
        elif not got_v:
            reasons.append("visual not loaded")
        if n_col == 0:
            reasons.append("no collision")
        elif not got_c:
            reasons.append("collision not loaded")
        if link.inertial is None:
            reasons.append("no <inertial>")
            mass, tensor = None, None
        else:
            mass, tensor = link.inertial.mass, link.inertial.inertia
            reasons += inertia_problems(mass, tensor, rtol)
        if mass is not None and tensor is not None and np.all(np.isfinite(tensor)):
            result.inertia[link.name] = (float(mass), np.sort(np.linalg.eigvalsh(0.5 * (tensor + tensor.T))))
        if reasons:
            result.link_problems[link.name] = reasons
        if joint.type not in ("revolute", "prismatic", "continuous"):
            result.fk_problems.append(f"joint {joint.name}: type {joint.type} is not checked")

    # Forward kinematics.
    link_names = {l.name for l in robot.links}
    common_model_checks(result, traj, link_names, movable)
    if result.fk_problems:
        return result
    for name in traj.joint_names:
        axis = np.asarray(movable[name].axis, dtype=np.float64)
        if abs(np.linalg.norm(axis) - 1.0) > 1e-9:
            # yourdfpy moves a prismatic joint by q * axis without normalising the axis.
            result.notes.append(f"joint {name}: axis norm {np.linalg.norm(axis):.12g} (URDF wants a unit axis)")

    def set_joints(q):
        model.update_cfg({n: float(v) for n, v in zip(traj.joint_names, q)})
        got = np.asarray([model.cfg[model.actuated_joint_names.index(n)] for n in traj.joint_names], dtype=np.float64)
        if np.max(np.abs(got - q), initial=0.0) != 0.0:
            raise RuntimeError("yourdfpy did not take the joint values as given")

    def link_from_base(link):
        return np.asarray(model.get_transform(frame_to=link, frame_from=base), dtype=np.float64)

    try:
        compare_key_points(result, traj, set_joints, link_from_base)
    except Exception as e:  # noqa: BLE001
        result.fk_problems.append(f"forward kinematics failed: {type(e).__name__}: {e}")
    return result


# ---------------------------------------------------------------------------------------
# Reader 2: pybullet
# ---------------------------------------------------------------------------------------


def check_pybullet(urdf_path: str, traj: Trajectory, rtol: float) -> ReaderResult:
    result = ReaderResult("pybullet")
    try:
        with captured_c_output():  # its import prints "pybullet build time: ..."
            import pybullet as pb
        from importlib.metadata import version

        result.version = version("pybullet")
    except Exception as e:  # noqa: BLE001
        result.load_problems.append(f"cannot import pybullet: {e}")
        return result

    client = -1
    try:
        with captured_c_output() as log:
            client = pb.connect(pb.DIRECT)
            try:
                body = pb.loadURDF(
                    os.path.abspath(urdf_path),
                    basePosition=[0.0, 0.0, 0.0],
                    baseOrientation=[0.0, 0.0, 0.0, 1.0],
                    useFixedBase=True,
                    # Keep the file's mass and inertia: without this flag pybullet replaces
                    # the inertia by one computed from the collision shapes.
                    flags=pb.URDF_USE_INERTIA_FROM_FILE,
                    physicsClientId=client,
                )
            except pb.error as e:
                body = None
                load_error = str(e)
        messages = [m.strip() for m in "".join(log).splitlines() if m.strip()]
        if body is None:
            result.load_problems.append(f"loadURDF failed: {load_error}")
            result.load_problems += [f"pybullet said: {m}" for m in messages if "build time" not in m][:10]
            return result
        # pybullet warns and goes on for a bad inertia; keep such lines.
        for m in messages:
            if "Bad inertia" in m or "cannot" in m.lower() or "could not" in m.lower():
                result.notes.append(f"pybullet said: {m}")
        return _pybullet_body_checks(pb, client, body, traj, rtol, result, messages)
    finally:
        if client >= 0:
            pb.disconnect(physicsClientId=client)


def _pybullet_body_checks(pb, client, body, traj, rtol, result, messages):
    kw = {"physicsClientId": client}
    base_name = pb.getBodyInfo(body, **kw)[0].decode()
    n = pb.getNumJoints(body, **kw)
    result.n_links = n + 1
    result.n_joints = n
    link_index = {base_name: -1}
    joint_index, movable = {}, {}
    joint_types = {pb.JOINT_REVOLUTE: "revolute", pb.JOINT_PRISMATIC: "prismatic", pb.JOINT_FIXED: "fixed"}
    for i in range(n):
        info = pb.getJointInfo(body, i, **kw)
        jname, jtype, child = info[1].decode(), info[2], info[12].decode()
        if child in link_index:
            result.load_problems.append(f"link {child} appears twice")
        link_index[child] = i
        joint_index[jname] = i
        if jtype != pb.JOINT_FIXED:
            movable[jname] = (i, child, joint_types.get(jtype, f"type {jtype}"))

    visuals = {}
    for shape in pb.getVisualShapeData(body, **kw):
        visuals.setdefault(shape[1], []).append(shape)
    n_vis = sum(len(v) for v in visuals.values())
    n_col = 0
    collisions = {}
    for i in range(-1, n):
        collisions[i] = list(pb.getCollisionShapeData(body, i, **kw))
        n_col += len(collisions[i])
    result.meshes = f"{n_vis} visual, {n_col} collision shape(s)"
    result.loaded = not result.load_problems

    result.n_movable = len(movable)
    for jname, (i, child, jtype) in movable.items():
        result.movable_links.append(child)
        reasons = []
        if not visuals.get(i):
            reasons.append("no visual")
        if not collisions.get(i):
            reasons.append("no collision")
        dyn = pb.getDynamicsInfo(body, i, **kw)
        mass, diagonal, inertial_orn = float(dyn[0]), np.asarray(dyn[2], dtype=np.float64), dyn[4]
        # pybullet keeps principal moments and the rotation of the principal axes; rebuild
        # the tensor in the inertial frame from them.
        rot = quat_to_matrix(inertial_orn)
        tensor = rot @ np.diag(diagonal) @ rot.T
        why = inertia_problems(mass, tensor, rtol)
        if any("Bad inertia" in m and m.rstrip().endswith(child) for m in messages):
            why.append("pybullet rejected the file's inertia (Bad inertia tensor properties) and set it to zero")
        reasons += why
        result.inertia[child] = (mass, np.sort(diagonal))
        if reasons:
            result.link_problems[child] = reasons
        if jtype not in ("revolute", "prismatic"):
            result.fk_problems.append(f"joint {jname}: {jtype} is not checked")

    common_model_checks(result, traj, set(link_index), {k: v for k, v in movable.items()})
    if result.fk_problems:
        return result

    # The base's URDF frame: getBasePositionAndOrientation gives its inertial (COM) frame.
    base_com = pose(*pb.getBasePositionAndOrientation(body, **kw))
    base_dyn = pb.getDynamicsInfo(body, -1, **kw)
    base_frame = base_com @ rigid_inverse(pose(base_dyn[3], base_dyn[4]))
    base_inv = rigid_inverse(base_frame)
    if np.max(np.abs(base_frame - np.eye(4))) > 1e-12:
        result.notes.append("base link frame is not the world frame; key points are mapped into it")
    indices = [joint_index[name] for name in traj.joint_names]
    all_links = list(range(n))
    states = {}
    worst_float32 = [0.0]

    def set_joints(q):
        for j, v in zip(indices, q):
            pb.resetJointState(body, j, float(v), 0.0, **kw)
        got = np.asarray([pb.getJointState(body, j, **kw)[0] for j in indices], dtype=np.float64)
        if np.max(np.abs(got - q), initial=0.0) != 0.0:
            raise RuntimeError("pybullet did not take the joint values as given")
        states.clear()
        if all_links:
            # getLinkState's worldLinkFramePosition/Orientation (indices 4, 5) is the URDF
            # link frame but comes back rounded to float32 (errors ~1e-7 m in pybullet
            # 3.2.7); the inertial (COM) frame (0, 1) and the local inertial frame (2, 3)
            # are doubles, and link frame = COM frame * inverse(local inertial frame).
            for j, s in zip(all_links, pb.getLinkStates(body, all_links, computeForwardKinematics=1, **kw)):
                states[j] = pose(s[0], s[1]) @ rigid_inverse(pose(s[2], s[3]))
                # Relative to the coordinates' size: float32 keeps about 7 digits.
                gap = float(np.linalg.norm(np.asarray(s[4], dtype=np.float64) - states[j][:3, 3]))
                worst_float32[0] = max(worst_float32[0], gap / max(1.0, float(np.linalg.norm(states[j][:3, 3]))))

    def link_from_base(link):
        i = link_index[link]
        return np.eye(4) if i == -1 else base_inv @ states[i]

    try:
        compare_key_points(result, traj, set_joints, link_from_base)
    except Exception as e:  # noqa: BLE001
        result.fk_problems.append(f"forward kinematics failed: {type(e).__name__}: {e}")
    # The two ways to the link frame must agree to float32 rounding, else one is misread.
    if worst_float32[0] > 1e-5:
        result.fk_problems.append(
            "link frame from the COM frame and worldLinkFramePosition differ by "
            f"{worst_float32[0]:.3g} (relative to max(1 m, |position|))"
        )
    else:
        result.notes.append(
            "link frames from the COM frames (float64); worldLinkFramePosition (float32) "
            f"agrees to {worst_float32[0]:.2g} relative"
        )
    return result


# ---------------------------------------------------------------------------------------
# Summary
# ---------------------------------------------------------------------------------------


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("urdf")
    ap.add_argument("trajectory")
    ap.add_argument("--fk-tol", type=float, default=FK_TOL_M, help="largest key point error, m (1e-6)")
    ap.add_argument("--inertia-rtol", type=float, default=INERTIA_RTOL, help="relative tolerance of the inertia checks (1e-6)")
    ap.add_argument("--readers", default="yourdfpy,pybullet", help="comma-separated: yourdfpy,pybullet")
    args = ap.parse_args(argv)

    readers = [r.strip() for r in args.readers.split(",") if r.strip()]
    bad = [r for r in readers if r not in ("yourdfpy", "pybullet")]
    if bad or not readers:
        ap.error(f"unknown reader(s): {', '.join(bad) or '(none)'}")
    for path in (args.urdf, args.trajectory):
        if not os.path.isfile(path):
            ap.error(f"{path}: no such file")

    passed = failed = 0

    def verdict(ok: bool) -> str:
        nonlocal passed, failed
        if ok:
            passed += 1
            return "ok"
        failed += 1
        return "FAIL"

    print(f"URDF check: {args.urdf}")
    try:
        traj = load_trajectory(args.trajectory)
    except Exception as e:  # noqa: BLE001
        print(f"trajectory {args.trajectory}: cannot read: {type(e).__name__}: {e}")
        print(f"urdf-check: 0 passed, 1 failed")
        return 1
    print(
        f"trajectory: {len(traj.samples)} sample(s), {len(traj.joint_names)} joint(s), "
        f"{len(traj.key_points)} key point(s)  [{verdict(not traj.problems)}]"
    )
    for p in traj.problems[:MAX_REASONS_SHOWN]:
        print(f"  - {p}")

    results = []
    for name in readers:
        check = check_yourdfpy if name == "yourdfpy" else check_pybullet
        try:
            r = check(args.urdf, traj, args.inertia_rtol)
        except Exception as e:  # noqa: BLE001  (a reader's crash is a failure, not a traceback)
            r = ReaderResult(name)
            r.load_problems.append(f"check crashed: {type(e).__name__}: {e}")
        results.append(r)
        print(f"[{r.name} {r.version}]")
        print(
            f"  load: {r.n_links} links, {r.n_joints} joints ({r.n_movable} movable); {r.meshes or 'no model'}"
            f"  [{verdict(r.loaded)}]"
        )
        for p in r.load_problems[:MAX_REASONS_SHOWN]:
            print(f"    - {p}")
        if r.n_links:
            n_bad = len(r.link_problems)
            print(
                f"  links: {len(r.movable_links) - n_bad} of {len(r.movable_links)} movable links have "
                f"visual + collision geometry, mass and a valid inertia  [{verdict(n_bad == 0 and bool(r.movable_links))}]"
            )
            if not r.movable_links:
                print("    - no movable links")
            for link, reasons in list(r.link_problems.items())[:MAX_REASONS_SHOWN]:
                print(f"    - {link}: {'; '.join(reasons)}")
        if r.n_links:
            fk_ok = not r.fk_problems and r.fk_points > 0 and r.fk_max_err <= args.fk_tol
            err = "n/a" if r.fk_points == 0 else f"{r.fk_max_err:.3g} m ({r.fk_where})"
            print(
                f"  fk: max key point error {err} over {r.fk_points} key point positions in "
                f"{len(traj.samples)} samples, tol {args.fk_tol:g} m  [{verdict(fk_ok)}]"
            )
            for p in r.fk_problems[:MAX_REASONS_SHOWN]:
                print(f"    - {p}")
        for note in list(dict.fromkeys(r.notes))[:MAX_REASONS_SHOWN]:
            print(f"  note: {note}")

    # The two readers against each other: mass and principal moments of the movable links.
    if len(results) == 2 and all(r.inertia for r in results):
        a, b = results
        diffs = []
        for link in sorted(set(a.inertia) | set(b.inertia)):
            if link not in a.inertia or link not in b.inertia:
                diffs.append(f"{link}: only one reader has its inertia")
                continue
            (ma, ia), (mb, ib) = a.inertia[link], b.inertia[link]
            scale = max(float(np.max(np.abs(ia))), float(np.max(np.abs(ib))), 1e-300)
            if abs(ma - mb) > args.inertia_rtol * max(abs(ma), abs(mb), 1e-300) or np.max(np.abs(ia - ib)) > args.inertia_rtol * scale:
                diffs.append(f"{link}: mass {ma:.6g} vs {mb:.6g}, principal moments {fmt_vec(ia)} vs {fmt_vec(ib)}")
        print(f"readers agree on mass and principal moments of {len(a.inertia)} movable link(s)  [{verdict(not diffs)}]")
        for d in diffs[:MAX_REASONS_SHOWN]:
            print(f"    - {d}")

    print(f"RESULT: {'PASS' if failed == 0 else 'FAIL'}")
    print(f"urdf-check: {passed} passed, {failed} failed")
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
