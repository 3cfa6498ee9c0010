"""Procedural texture images: wood grain, brushed metal, fine noise and printed rule
graduations (numpy only).

Every image is a function of the material's ``texture_params`` alone (their first entry
seeds the noise), so the same object gives the same bytes. Images tile seamlessly: the
noise is white noise filtered in the Fourier domain, which is periodic by construction,
and wood rings use whole numbers of periods per tile. One tile covers
:data:`TILE_METRES` of surface (UVs are metres divided by it, see
:func:`artipg.export.meshes.primitive_surface_arrays`): the grain has the same scale on
every part. Wood grain and brushed streaks run along v (a primitive's long side).
"""

from __future__ import annotations

import struct
import zlib

import numpy as np

#: Side of one texture tile on the surface, metres.
TILE_METRES = 0.5
#: Side of a texture image, pixels.
SIZE = 256


def periodic_noise(rng: np.random.Generator, size: int, scale_u: float, scale_v: float) -> np.ndarray:
    """Tileable Gaussian noise (size, size) with zero mean and unit deviation.

    ``scale_u``, ``scale_v``: correlation lengths in pixels along u (columns) and v (rows).
    """
    white = rng.standard_normal((size, size))
    fv, fu = np.fft.fftfreq(size), np.fft.rfftfreq(size)
    gain = np.exp(-2.0 * np.pi ** 2 * ((fv[:, None] * scale_v) ** 2 + (fu[None, :] * scale_u) ** 2))
    out = np.fft.irfft2(np.fft.rfft2(white) * gain, s=(size, size))
    return (out - out.mean()) / max(out.std(), 1e-12)


def _wood(params, size: int) -> np.ndarray:
    seed, r0, g0, b0, r1, g1, b1, rings, wave = params
    rng = np.random.default_rng(int(seed))
    u = np.arange(size) / size
    warp = periodic_noise(rng, size, 24.0, 48.0) * 0.04 * wave + periodic_noise(rng, size, 6.0, 60.0) * 0.006
    phase = (u[None, :] + warp) * round(rings)  # whole periods per tile: seamless
    ring = np.abs(np.sin(np.pi * phase)) ** 6  # thin dark late-wood bands
    fibre = periodic_noise(rng, size, 1.0, 30.0) * 0.06
    t = np.clip(ring * 0.85 + fibre + 0.1, 0.0, 1.0)[..., None]
    return (1.0 - t) * np.array([r0, g0, b0]) + t * np.array([r1, g1, b1])


def _brushed(params, size: int) -> np.ndarray:
    seed, r, g, b, strength = params
    rng = np.random.default_rng(int(seed))
    streak = periodic_noise(rng, size, 0.6, 60.0)
    return np.array([r, g, b]) * (1.0 + strength * 0.5 * streak)[..., None]


def _noise(params, size: int) -> np.ndarray:
    seed, r, g, b, strength = params
    rng = np.random.default_rng(int(seed))
    n = periodic_noise(rng, size, 1.2, 1.2) * 0.6 + periodic_noise(rng, size, 12.0, 12.0) * 0.4
    return np.array([r, g, b]) * (1.0 + strength * n)[..., None]


def _scale(params, size: int) -> np.ndarray:
    """Printed graduations of a rule: millimetre, half-centimetre and centimetre ticks
    along v (rows), starting at v = 0 (a part's end) and reaching in from u = 0 (its
    edge), on a plain ground (plain rows keep the large image small as PNG)."""
    seed, r, g, b, ir, ig, ib = params
    img = np.empty((size, size, 3), dtype=np.float32)
    img[:] = np.array([r, g, b], dtype=np.float32)
    px = size / TILE_METRES  # pixels per metre
    k = np.arange(int(round(TILE_METRES * 1000)))  # one tick per millimetre of the tile
    length = np.rint(np.where(k % 10 == 0, 0.0045, np.where(k % 5 == 0, 0.003, 0.0018)) * px).astype(int)
    rows = (size - 1 - np.floor(k * 0.001 * px).astype(int)) % size  # row 0 is v = 1
    ink = np.array([ir, ig, ib], dtype=np.float32)
    for d in range(max(1, int(round(0.0002 * px)))):  # printed lines 0.2 mm wide
        for row, n in zip((rows - d) % size, length):
            img[row, :n] = ink
    return img


_KINDS = {"wood": _wood, "brushed": _brushed, "noise": _noise, "scale": _scale}
#: Image side (pixels) of the kinds that need finer detail than :data:`SIZE`
#: (millimetre ticks: 0.24 mm per pixel).
KIND_SIZE = {"scale": 2048}


def texture_image(kind: str, params, size: int | None = None) -> np.ndarray:
    """The texture image (size, size, 3) uint8, sRGB, of kind ``kind`` with ``params``
    (:attr:`artipg.appearance.Material.texture_params`); row 0 is v = 1 (image order).
    ``size`` defaults to the kind's (:data:`KIND_SIZE`, else :data:`SIZE`)."""
    try:
        fn = _KINDS[kind]
    except KeyError:
        raise ValueError(f"unknown texture kind {kind!r}; known: {', '.join(_KINDS)}") from None
    img = fn(tuple(params), size or KIND_SIZE.get(kind, SIZE))
    return np.clip(np.rint(img * 255.0), 0, 255).astype(np.uint8)


def png_bytes(img: np.ndarray) -> bytes:
    """PNG bytes of an RGB image (H, W, 3) uint8 (no filter, zlib level 1: noise hardly compresses): a few lines
    of the PNG specification instead of a dependency for export."""
    h, w, _ = img.shape
    raw = np.concatenate([np.zeros((h, 1), np.uint8), img.reshape(h, w * 3)], axis=1).tobytes()

    def chunk(tag: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data))

    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw, 1)) + chunk(b"IEND", b""))


def texture_png(material, size: int | None = None) -> bytes:
    """PNG bytes of ``material``'s texture image (its ``texture_file``)."""
    return png_bytes(texture_image(material.texture, material.texture_params, size))
