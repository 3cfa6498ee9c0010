"""The simulator formats of an object folder beside its URDF, by name.

``urdf`` (``mobility.urdf``, always written: the others are derived from it),
``mjcf`` (``mobility.xml``), ``usd`` (``mobility.usd``) and ``glb`` (``mobility.glb``).
"""

from __future__ import annotations

FORMATS = ("urdf", "mjcf", "usd", "glb")

#: File name of each format in the object folder.
FILE_NAME = {"urdf": "mobility.urdf", "mjcf": "mobility.xml", "usd": "mobility.usd", "glb": "mobility.glb"}

#: What ``artipg generate`` writes unless told otherwise: URDF and MJCF are text files
#: sharing the meshes, cheap to write and loaded by every simulator but Isaac; USD and
#: GLB embed the geometry again (larger, slower) and are one flag away.
DEFAULT_FORMATS = ("urdf", "mjcf")


def parse_formats(text) -> tuple[str, ...]:
    """Format names from ``"urdf,mjcf"`` (or a sequence of names), in :data:`FORMATS`
    order, without repeats; raises ``ValueError`` naming an unknown one."""
    names = text.split(",") if isinstance(text, str) else list(text)
    names = [n.strip().lower() for n in names if n.strip()]
    bad = [n for n in names if n not in FORMATS]
    if bad:
        raise ValueError(f"unknown format {bad[0]!r}; formats: {', '.join(FORMATS)}")
    if not names:
        raise ValueError(f"no format given; formats: {', '.join(FORMATS)}")
    return tuple(f for f in FORMATS if f in names)


def format_files(asset, formats, actuators: bool = False) -> dict[str, bytes]:
    """{file name: bytes} of the non-URDF ``formats`` of ``asset``
    (:class:`artipg.export.asset.Asset`)."""
    out = {}
    if "mjcf" in formats:
        from artipg.export.mjcf import build_mjcf, mjcf_text

        out[FILE_NAME["mjcf"]] = mjcf_text(build_mjcf(asset, actuators=actuators)).encode()
    if "usd" in formats:
        from artipg.export.usd import usd_bytes

        out[FILE_NAME["usd"]] = usd_bytes(asset, actuators=actuators)
    if "glb" in formats:
        from artipg.export.glb import glb_bytes

        out[FILE_NAME["glb"]] = glb_bytes(asset)
    return out
