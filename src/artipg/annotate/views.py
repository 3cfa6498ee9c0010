"""Partial observations: depth images, per-pixel labels and back-projected clouds.

Cameras are pinhole cameras in the OpenCV convention (camera +z looks forward, +x
right, +y down) placed on a sphere around the object's bounding-box centre and
looking at it. Images are ray cast on the CPU with Embree (``embreex`` through
``trimesh``) against the object's labelled mesh at the requested joint state.

Viewing angles, in degrees: ``azimuth`` 0 puts the camera in front of the object
(on the -x side, looking along +x); it grows counter-clockwise seen from above, so
azimuth 90 looks from -y (the viewer's right side of the object) and 180 from the
back. ``elevation`` is the angle above the horizontal plane through the centre.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np
import trimesh

from artipg.annotate.mesh import posed_mesh
from artipg.vocabulary import label_id

#: Azimuth and elevation ranges (degrees) of the partial-view cameras (paper sec. 4.2).
AZIMUTH_RANGE = (0.0, 360.0)
ELEVATION_RANGE = (30.0, 60.0)


@dataclass(frozen=True)
class Camera:
    """A pinhole camera.

    Attributes
    ----------
    pose : (4, 4) ndarray
        Camera frame in the object frame (OpenCV axes: +z forward, +x right, +y down).
    K : (3, 3) ndarray
        Intrinsics in pixels (pixel centres at integer + 0.5).
    width, height : int
        Image size in pixels.
    azimuth, elevation : float
        Viewing angles in degrees (see the module docstring).
    """

    pose: np.ndarray
    K: np.ndarray
    width: int
    height: int
    azimuth: float = 0.0
    elevation: float = 0.0


def look_at(eye, target, up=(0.0, 0.0, 1.0)) -> np.ndarray:
    """Camera pose (4, 4) at ``eye`` looking at ``target`` (OpenCV axes), object frame."""
    eye = np.asarray(eye, dtype=float)
    f = np.asarray(target, dtype=float) - eye
    f /= np.linalg.norm(f)
    r = np.cross(f, np.asarray(up, dtype=float))
    if np.linalg.norm(r) < 1e-9:  # looking straight down or up
        r = np.cross(f, np.array([1.0, 0.0, 0.0]))
    r /= np.linalg.norm(r)
    d = np.cross(f, r)  # image down
    T = np.eye(4)
    T[:3, 0], T[:3, 1], T[:3, 2], T[:3, 3] = r, d, f, eye
    return T


def view_direction(azimuth: float, elevation: float) -> np.ndarray:
    """Unit vector (3,) from the target towards a camera at these angles (degrees)."""
    a, e = math.radians(azimuth), math.radians(elevation)
    return np.array([-math.cos(a) * math.cos(e), -math.sin(a) * math.cos(e), math.sin(e)])


def orbit_camera(center, radius: float, azimuth: float, elevation: float, width: int = 640, height: int = 480,
                 fov_deg: float = 45.0, margin: float = 1.08) -> Camera:
    """A camera looking at ``center`` from (azimuth, elevation), far enough to see a
    sphere of ``radius`` metres around it whole.

    Parameters
    ----------
    center : (3,) array_like
        Target point, object frame (metres).
    radius : float
        Radius of the sphere that must fit in the image (metres).
    azimuth, elevation : float
        Degrees (see the module docstring).
    width, height : int
        Image size in pixels.
    fov_deg : float
        Vertical field of view in degrees (square pixels).
    margin : float
        Extra distance factor (> 1 leaves a border).
    """
    fy = 0.5 * height / math.tan(math.radians(fov_deg) / 2)
    half = min(math.atan(0.5 * height / fy), math.atan(0.5 * width / fy))
    dist = margin * radius / math.sin(half)
    eye = np.asarray(center, dtype=float) + dist * view_direction(azimuth, elevation)
    K = np.array([[fy, 0.0, width / 2], [0.0, fy, height / 2], [0.0, 0.0, 1.0]])
    return Camera(look_at(eye, center), K, int(width), int(height), float(azimuth), float(elevation))


def fit_camera(obj, qpos=None, azimuth: float = 35.0, elevation: float = 25.0, width: int = 640, height: int = 480,
               fov_deg: float = 40.0, fill: float = 0.92) -> Camera:
    """An orbit camera at (azimuth, elevation) looking at the object's bounding-box
    centre from the distance at which the box's projection fills ``fill`` of the
    image along its tighter dimension (for pictures; datasets use
    :func:`hemisphere_cameras`, whose distance does not depend on the view)."""
    from artipg.geometry.base import _CORNER_SIGNS

    b = obj.bounds(qpos)
    c, r = object_sphere(obj, qpos)
    corners = b[0] + _CORNER_SIGNS * (b[1] - b[0])
    cam = orbit_camera(c, r, azimuth, elevation, width, height, fov_deg)
    for _ in range(3):
        Ti = np.linalg.inv(cam.pose)
        p = corners @ Ti[:3, :3].T + Ti[:3, 3]
        u = np.abs(p[:, 0] / p[:, 2]) * cam.K[0, 0] / (width / 2)
        v = np.abs(p[:, 1] / p[:, 2]) * cam.K[1, 1] / (height / 2)
        ext = max(u.max(), v.max()) / fill
        dist = np.linalg.norm(cam.pose[:3, 3] - c)
        # extents scale about inversely with the distance to the target
        new = max(dist * ext, 1.05 * r)
        eye = c + new * view_direction(azimuth, elevation)
        cam = Camera(look_at(eye, c), cam.K, width, height, float(azimuth), float(elevation))
    return cam


def object_sphere(obj, qpos=None) -> tuple[np.ndarray, float]:
    """Centre (3,) and radius of the bounding box's circumsphere at ``qpos`` (metres)."""
    b = obj.bounds(qpos)
    return (b[0] + b[1]) / 2, float(np.linalg.norm(b[1] - b[0]) / 2)


def hemisphere_cameras(obj, k: int, rng: np.random.Generator, qpos=None, width: int = 320, height: int = 240,
                       azimuth_range=AZIMUTH_RANGE, elevation_range=ELEVATION_RANGE, fov_deg: float = 45.0
                       ) -> list[Camera]:
    """``k`` cameras with azimuth and elevation drawn uniformly from the given ranges
    (degrees) looking at the object's bounding-box centre at ``qpos``."""
    c, r = object_sphere(obj, qpos)
    az = rng.uniform(*azimuth_range, size=k)
    el = rng.uniform(*elevation_range, size=k)
    return [orbit_camera(c, r, a, e, width, height, fov_deg) for a, e in zip(az, el)]


@lru_cache(maxsize=16)
def _pixel_directions(width: int, height: int, K: tuple) -> tuple[np.ndarray, np.ndarray]:
    fx, cx, fy, cy = K
    u, v = np.meshgrid(np.arange(width, dtype=np.float64) + 0.5, np.arange(height, dtype=np.float64) + 0.5)
    d = np.stack([(u.ravel() - cx) / fx, (v.ravel() - cy) / fy, np.ones(u.size)], axis=1)
    n = np.sqrt((d * d).sum(axis=1))
    d /= n[:, None]
    d.flags.writeable = False
    cosang = 1.0 / n
    cosang.flags.writeable = False
    return d, cosang


def camera_rays(cam: Camera, pixels: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Ray origins (k, 3), unit directions (k, 3) in the object frame and the cosine
    (k,) between each ray and the optical axis, for the flat (row-major) pixel
    indices ``pixels`` (all H*W pixels by default)."""
    K = cam.K
    d, cosang = _pixel_directions(cam.width, cam.height, (K[0, 0], K[0, 2], K[1, 1], K[1, 2]))
    if pixels is not None:
        d, cosang = d[pixels], cosang[pixels]
    R = cam.pose[:3, :3]
    # three scaled columns instead of a (N, 3) @ (3, 3) product: no BLAS threads
    dirs = d[:, :1] * R[:, 0] + d[:, 1:2] * R[:, 1] + d[:, 2:] * R[:, 2]
    return np.broadcast_to(cam.pose[:3, 3], dirs.shape), dirs, cosang


def cast_rays(mesh: trimesh.Trimesh, origins: np.ndarray, dirs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """First hits of rays on ``mesh``: distance (N,) along each unit direction (inf
    on a miss) and face index (N,) (-1 on a miss). Embree, single precision."""
    try:
        from embreex import rtcore_scene
        from embreex.mesh_construction import TriangleMesh
    except ImportError:  # pragma: no cover - no Embree: trimesh's slow pure-numpy caster
        loc, ray, tri = mesh.ray.intersects_location(origins, dirs, multiple_hits=False)
        t = np.full(len(dirs), np.inf)
        face = np.full(len(dirs), -1, dtype=np.int64)
        t[ray] = np.linalg.norm(loc - origins[ray], axis=1)
        face[ray] = tri
        return t, face
    # shift to the first origin so single precision keeps sub-micrometre resolution
    o = np.asarray(origins[0], dtype=float)
    scene = rtcore_scene.EmbreeScene()
    TriangleMesh(scene=scene, vertices=(np.asarray(mesh.vertices) - o).astype(np.float32),
                 indices=np.asarray(mesh.faces, dtype=np.int32))
    res = scene.run(np.ascontiguousarray(origins - o, dtype=np.float32), np.ascontiguousarray(dirs, dtype=np.float32),
                    output=1)
    face = res["primID"].astype(np.int64)
    hit = (face >= 0) & (res["geomID"] >= 0)
    face[~hit] = -1
    t = np.where(hit, res["tfar"].astype(np.float64), np.inf)
    return t, face


def _pixels_in_box(cam: Camera, box: np.ndarray) -> np.ndarray:
    """Flat indices of the pixels whose rays can meet the axis-aligned ``box`` (2, 3)
    (all pixels when the camera is inside it or behind-camera corners occur)."""
    from artipg.geometry.base import _CORNER_SIGNS

    c = box[0] + _CORNER_SIGNS * (box[1] - box[0])
    Tinv = np.linalg.inv(cam.pose)
    pc = c @ Tinv[:3, :3].T + Tinv[:3, 3]
    if np.any(pc[:, 2] <= 1e-6):
        return np.arange(cam.width * cam.height)
    uv = pc[:, :2] / pc[:, 2:] * np.diag(cam.K)[:2] + cam.K[:2, 2]
    c0, r0 = np.floor(uv.min(axis=0) - 1).astype(int)
    c1, r1 = np.ceil(uv.max(axis=0) + 1).astype(int)
    c0, c1 = max(c0, 0), min(c1, cam.width)
    r0, r1 = max(r0, 0), min(r1, cam.height)
    if c0 >= c1 or r0 >= r1:
        return np.zeros(0, dtype=np.int64)
    rows, cols = np.mgrid[r0:r1, c0:c1]
    return (rows * cam.width + cols).ravel()


def _face_normals(mesh: trimesh.Trimesh, faces: np.ndarray) -> np.ndarray:
    """Unit normals (k, 3) of the given faces (no cache of all face normals)."""
    v = np.asarray(mesh.vertices)[np.asarray(mesh.faces)[faces]]
    n = np.cross(v[:, 1] - v[:, 0], v[:, 2] - v[:, 0])
    return n / np.maximum(np.linalg.norm(n, axis=1), 1e-30)[:, None]


@dataclass
class View:
    """One rendered view.

    Attributes
    ----------
    camera : Camera
    depth : (H, W) float32
        z-depth along the camera's optical axis in metres, 0 where no surface is hit.
    points : (H, W, 3) float32
        Hit points in the object frame (metres), 0 where nothing is hit.
    normal : (H, W, 3) float32
        Unit face normal of the hit triangle (object frame), turned towards the camera.
    primitive, semantic, instance, link : (H, W) int32
        Global primitive index and labels of the hit (see :class:`PointCloud`), -1 on
        background pixels.
    """

    camera: Camera
    depth: np.ndarray
    points: np.ndarray
    normal: np.ndarray
    primitive: np.ndarray
    semantic: np.ndarray
    instance: np.ndarray
    link: np.ndarray

    @property
    def mask(self) -> np.ndarray:
        """Foreground mask (H, W) bool."""
        return self.primitive >= 0


def render_view(obj, cam: Camera, qpos=None, sections: int = 32, exclude: tuple = ()) -> View:
    """Ray cast ``obj`` at ``qpos`` from ``cam``: depth, hit points, normals and labels.

    Parameters
    ----------
    obj : ArticulatedObject
    cam : Camera
    qpos : None, dict or sequence
        Joint state.
    sections : int
        Segments of curved primitives in the ray-cast mesh.
    exclude : tuple of str
        Semantic labels whose parts the rays pass through (pictures seen through glass).
    """
    mesh, face_prim = posed_mesh(obj, qpos, sections)
    if exclude:
        t = obj.primitive_table
        ids = [label_id(name) for name in exclude]
        keep = ~np.isin(t.part_semantic[t.prim_part[face_prim]], ids)
        mesh = trimesh.Trimesh(mesh.vertices, mesh.faces[keep], process=False, validate=False)
        face_prim = face_prim[keep]
    H, W = cam.height, cam.width
    n = H * W
    # only rays inside the object's projected bounding box can hit it
    sel = _pixels_in_box(cam, obj.bounds(qpos))
    origins, dirs, cosang = camera_rays(cam, sel)
    t, face = cast_rays(mesh, origins, dirs) if len(sel) else (np.zeros(0), np.zeros(0, dtype=np.int64))
    hit = face >= 0
    ray = sel[hit]
    tri = face[hit]
    th = t[hit]
    dh = dirs[hit]
    prim = np.full(n, -1, dtype=np.int32)
    prim[ray] = face_prim[tri]
    pts = np.zeros((n, 3), dtype=np.float32)
    pts[ray] = cam.pose[:3, 3] + dh * th[:, None]
    depth = np.zeros(n, dtype=np.float32)
    depth[ray] = th * cosang[hit]
    fn = _face_normals(mesh, tri)
    flip = np.einsum("ij,ij->i", fn, dh) > 0
    fn[flip] *= -1
    nrm = np.zeros((n, 3), dtype=np.float32)
    nrm[ray] = fn
    table = obj.primitive_table
    part = np.where(prim >= 0, table.prim_part[np.maximum(prim, 0)], -1)
    sem = np.where(prim >= 0, table.part_semantic[np.maximum(part, 0)], -1)
    link = np.where(prim >= 0, table.prim_link[np.maximum(prim, 0)], -1)
    shape = (H, W)
    return View(cam, depth.reshape(shape), pts.reshape(H, W, 3), nrm.reshape(H, W, 3), prim.reshape(shape),
                sem.reshape(shape).astype(np.int32), part.reshape(shape).astype(np.int32),
                link.reshape(shape).astype(np.int32))


@dataclass
class PartialCloud:
    """A partial point cloud back-projected from one view (object frame).

    Attributes
    ----------
    points : (n, 3) float64
        Surface points seen by the camera (metres, object frame).
    pixels : (n, 2) int64
        (row, column) of each point in the view.
    primitive, semantic, instance, link : (n,) int64
        Labels of each point (see :class:`artipg.annotate.points.PointCloud`).
    camera : Camera
    view : View
        The rendered view the points come from.
    """

    points: np.ndarray
    pixels: np.ndarray
    primitive: np.ndarray
    semantic: np.ndarray
    instance: np.ndarray
    link: np.ndarray
    camera: Camera
    view: View | None = None


def backproject(view: View) -> np.ndarray:
    """Points (H, W, 3) in the object frame from ``view.depth`` and the camera model
    (NaN on background pixels); equal to ``view.points`` up to float32 rounding."""
    cam = view.camera
    fg = np.flatnonzero(view.mask.ravel())
    _, dirs, cosang = camera_rays(cam, fg)
    r = view.depth.ravel()[fg].astype(float) / cosang
    p = np.full((cam.width * cam.height, 3), np.nan)
    p[fg] = cam.pose[:3, 3] + dirs * r[:, None]
    return p.reshape(cam.height, cam.width, 3)


def partial_cloud(view: View, n: int, rng: np.random.Generator) -> PartialCloud:
    """Pick ``n`` foreground pixels of ``view`` uniformly (with replacement only when
    fewer are visible) and return their back-projected, labelled points."""
    fg = np.flatnonzero(view.mask.ravel())
    if not len(fg):
        raise ValueError("the view sees nothing of the object")
    pick = rng.choice(fg, size=n, replace=len(fg) < n)
    rows, cols = np.divmod(pick, view.camera.width)
    pts = backproject(view).reshape(-1, 3)[pick]
    return PartialCloud(pts, np.stack([rows, cols], axis=1), view.primitive.ravel()[pick].astype(np.int64),
                        view.semantic.ravel()[pick].astype(np.int64), view.instance.ravel()[pick].astype(np.int64),
                        view.link.ravel()[pick].astype(np.int64), view.camera, view)


def partial_views(obj, k: int = 8, n: int = 2048, qpos=None, seed: int = 0, width: int = 320, height: int = 240,
                  **camera_kw) -> list[PartialCloud]:
    """``k`` partial clouds of ``n`` points each from random upper-hemisphere cameras.

    Parameters
    ----------
    obj : ArticulatedObject
    k : int
        Number of views.
    n : int
        Points per view.
    qpos : None, dict or sequence
        Joint state.
    seed : int
        Seed of the camera and pixel draws.
    width, height : int
        Image size of each view in pixels (the points are drawn from its pixels).
    **camera_kw
        Passed to :func:`hemisphere_cameras` (``azimuth_range``, ``elevation_range``,
        ``fov_deg``).
    """
    rng = np.random.default_rng(seed)
    cams = hemisphere_cameras(obj, k, rng, qpos, width, height, **camera_kw)
    return [partial_cloud(render_view(obj, c, qpos), n, rng) for c in cams]
