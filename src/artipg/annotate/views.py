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

import numpy as np
import trimesh

from artipg.annotate.mesh import posed_mesh

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


def camera_rays(cam: Camera) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Ray origins (H*W, 3), unit directions (H*W, 3) in the object frame and the
    cosine (H*W,) between each ray and the optical axis (row-major pixel order)."""
    u, v = np.meshgrid(np.arange(cam.width) + 0.5, np.arange(cam.height) + 0.5)
    K = cam.K
    d = np.stack([(u.ravel() - K[0, 2]) / K[0, 0], (v.ravel() - K[1, 2]) / K[1, 1], np.ones(u.size)], axis=1)
    n = np.linalg.norm(d, axis=1)
    d /= n[:, None]
    dirs = d @ cam.pose[:3, :3].T
    return np.broadcast_to(cam.pose[:3, 3], dirs.shape), dirs, 1.0 / n


def _intersector(mesh: trimesh.Trimesh):
    try:
        from trimesh.ray.ray_pyembree import RayMeshIntersector
    except ImportError:  # pragma: no cover - embreex missing: slow pure-python fallback
        from trimesh.ray.ray_triangle import RayMeshIntersector
    return RayMeshIntersector(mesh)


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


def render_view(obj, cam: Camera, qpos=None, sections: int = 32) -> View:
    """Ray cast ``obj`` at ``qpos`` from ``cam``: depth, hit points, normals and labels.

    Parameters
    ----------
    obj : ArticulatedObject
    cam : Camera
    qpos : None, dict or sequence
        Joint state.
    sections : int
        Segments of curved primitives in the ray-cast mesh.
    """
    mesh, face_prim = posed_mesh(obj, qpos, sections)
    origins, dirs, cosang = camera_rays(cam)
    loc, ray, tri = _intersector(mesh).intersects_location(np.ascontiguousarray(origins), dirs,
                                                           multiple_hits=False)
    H, W = cam.height, cam.width
    n = H * W
    prim = np.full(n, -1, dtype=np.int32)
    prim[ray] = face_prim[tri]
    pts = np.zeros((n, 3), dtype=np.float32)
    pts[ray] = loc
    depth = np.zeros(n, dtype=np.float32)
    depth[ray] = np.linalg.norm(loc - origins[ray], axis=1) * cosang[ray]
    fn = mesh.face_normals[tri]
    flip = np.einsum("ij,ij->i", fn, dirs[ray]) > 0
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
