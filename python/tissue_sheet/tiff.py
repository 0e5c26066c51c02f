"""A minimal multi-page TIFF writer for label volumes and layers (no dependency beyond numpy).

Writes what ``tissue-sheet measure`` reads: one uncompressed page per z-slice, one unsigned 8-,
16- or 32-bit sample per pixel, little-endian, one strip per page, and an ImageJ description
with the voxel size (``unit=micron``, ``spacing=``) and X/YResolution in pixels per µm, so the
file also opens in Fiji with its calibration. ``write_layer_tiff`` writes one 2D layer of the
layers mode (one page, 8 or 16 bits: that mode reads no 32-bit labels).
"""

from __future__ import annotations

import os
import struct
from fractions import Fraction
from typing import Sequence

import numpy as np

_SHORT, _LONG, _RATIONAL, _ASCII = 3, 4, 5, 2


def _rational(value: float) -> tuple[int, int]:
    f = Fraction(value).limit_denominator(1_000_000)
    if f.numerator >= 2**32 or f.denominator >= 2**32 or f <= 0:
        raise ValueError(f"resolution {value} cannot be written as a TIFF rational")
    return f.numerator, f.denominator


def label_dtype(labels: np.ndarray) -> np.dtype:
    """The smallest unsigned type holding the labels (refuses negatives, floats with fractions, over 2^32 - 1)."""
    if labels.dtype.kind == "b":
        raise ValueError("labels: a boolean mask, not a label volume (one integer per cell, 0 background)")
    if labels.dtype.kind not in "uif":
        raise ValueError(f"labels: dtype {labels.dtype} is not numeric")
    if labels.size == 0:
        raise ValueError("labels: the array is empty")
    if labels.dtype.kind == "f":
        if not np.all(np.isfinite(labels)) or not np.all(labels == np.round(labels)):
            raise ValueError("labels: float values that are not whole numbers (labels are integers)")
    lo, hi = labels.min(), labels.max()
    if lo < 0:
        raise ValueError(f"labels: negative value {lo} (labels are 0 for background and positive integers)")
    if hi < 2**8:
        return np.dtype("<u1")
    if hi < 2**16:
        return np.dtype("<u2")
    if hi < 2**32:
        return np.dtype("<u4")
    raise ValueError(f"labels: value {hi} is over 2^32 - 1")


def write_label_tiff(path: str | os.PathLike, labels: np.ndarray, voxel_size: Sequence[float]) -> None:
    """Writes a (z, y, x) label array as a multi-page TIFF with ImageJ voxel-size metadata.

    ``voxel_size``: (x, y, z) in µm: along the image width, its height, and between pages.
    """
    labels = np.asarray(labels)
    if labels.ndim != 3:
        raise ValueError(f"labels: a 3D array (z, y, x) is needed, got {labels.ndim} dimensions {labels.shape}")
    depth, height, width = labels.shape
    if depth < 2:
        raise ValueError(f"labels: at least two z-slices are needed, got {depth}")
    if len(voxel_size) != 3 or not all(isinstance(v, (int, float, np.number)) and np.isfinite(v) and v > 0 for v in voxel_size):
        raise ValueError(f"voxel_size: three positive numbers (x, y, z) in µm are needed, got {voxel_size!r}")
    x, y, z = (float(v) for v in voxel_size)
    description = f"ImageJ=1.54f\nimages={depth}\nslices={depth}\nunit=micron\nspacing={z!r}\nloop=false\n"
    _write_pages(path, labels, label_dtype(labels), x, y, description)


def write_layer_tiff(path: str | os.PathLike, labels: np.ndarray, pixel_size: float) -> None:
    """Writes a (y, x) label image, one layer of ``tissue-sheet measure LAYER_FILE...``, as a one-page TIFF.

    ``pixel_size``: the (square) pixel's edge in µm. Labels up to 65,535: the layers mode reads
    8- and 16-bit images only.
    """
    labels = np.asarray(labels)
    if labels.ndim != 2:
        raise ValueError(f"labels: a 2D array (y, x) is needed for a layer, got {labels.ndim} dimensions {labels.shape}")
    if not (isinstance(pixel_size, (int, float, np.number)) and np.isfinite(pixel_size) and pixel_size > 0):
        raise ValueError(f"pixel_size: a positive number of µm is needed, got {pixel_size!r}")
    dtype = label_dtype(labels)
    if dtype.itemsize > 2:
        raise ValueError(f"labels: value {labels.max()} is over 65,535 (layer images hold 8- or 16-bit labels; renumber the cells)")
    _write_pages(path, labels[np.newaxis], dtype, float(pixel_size), float(pixel_size), "ImageJ=1.54f\nunit=micron\n")


def _write_pages(path: str | os.PathLike, labels: np.ndarray, dtype: np.dtype, x: float, y: float, description_text: str) -> None:
    """The TIFF itself: a (pages, y, x) array, ``x`` and ``y`` the pixel's size in µm, an ImageJ description."""
    depth, height, width = labels.shape
    data = np.ascontiguousarray(labels.astype(dtype, copy=False))
    bits = dtype.itemsize * 8
    page_bytes = width * height * dtype.itemsize
    description = description_text.encode("ascii") + b"\0"

    out = bytearray(b"II*\0" + struct.pack("<I", 0))
    first_ifd_at = 4
    previous_next = first_ifd_at
    for page in range(depth):
        # Pixel data first, then the IFD (and its out-of-line values) after it.
        while len(out) % 2:
            out.append(0)
        strip_at = len(out)
        out += data[page].tobytes()
        while len(out) % 2:
            out.append(0)
        extra: list[tuple[int, bytes]] = []  # (tag, bytes) placed after the IFD
        entries = [
            (256, _LONG, 1, width),
            (257, _LONG, 1, height),
            (258, _SHORT, 1, bits),
            (259, _SHORT, 1, 1),  # no compression
            (262, _SHORT, 1, 1),  # black is zero
            (273, _LONG, 1, strip_at),
            (277, _SHORT, 1, 1),
            (278, _LONG, 1, height),
            (279, _LONG, 1, page_bytes),
            (282, _RATIONAL, 1, None),
            (283, _RATIONAL, 1, None),
            (284, _SHORT, 1, 1),  # chunky
            (296, _SHORT, 1, 1),  # no absolute unit: ImageJ's unit= says µm
            (339, _SHORT, 1, 1),  # unsigned integers
        ]
        if page == 0:
            entries.append((270, _ASCII, len(description), None))
        entries.sort(key=lambda e: e[0])
        ifd_at = len(out)
        struct.pack_into("<I", out, previous_next, ifd_at)
        ifd_size = 2 + 12 * len(entries) + 4
        values_at = ifd_at + ifd_size
        out += struct.pack("<H", len(entries))
        for tag, kind, count, value in entries:
            if tag == 282:
                payload = struct.pack("<II", *_rational(1 / x))
            elif tag == 283:
                payload = struct.pack("<II", *_rational(1 / y))
            elif tag == 270:
                payload = description
            else:
                payload = None
            if payload is None:
                packed = struct.pack("<HHI", tag, kind, count) + (struct.pack("<HH", value, 0) if kind == _SHORT else struct.pack("<I", value))
            else:
                offset = values_at + sum(len(p) + len(p) % 2 for _, p in extra)
                extra.append((tag, payload))
                packed = struct.pack("<HHII", tag, kind, count, offset)
            out += packed
        previous_next = len(out)
        out += struct.pack("<I", 0)
        for _, payload in extra:
            out += payload
            if len(payload) % 2:
                out.append(0)
    with open(path, "wb") as f:
        f.write(out)


def read_label_tiff(path: str | os.PathLike) -> tuple[np.ndarray, dict]:
    """Reads back what write_label_tiff writes (uncompressed, one strip per page): (z, y, x) labels and tags.

    Only this module's own form; for tests and round trips, not a general TIFF reader.
    """
    data = open(path, "rb").read()
    if data[:4] != b"II*\0":
        raise ValueError(f"{path}: not a little-endian classic TIFF")
    (ifd,) = struct.unpack_from("<I", data, 4)
    pages, tags0 = [], None
    sizes = {_SHORT: 2, _LONG: 4, _RATIONAL: 8, _ASCII: 1}
    while ifd:
        (n,) = struct.unpack_from("<H", data, ifd)
        tags = {}
        for i in range(n):
            tag, kind, count, raw = struct.unpack_from("<HHI4s", data, ifd + 2 + 12 * i)
            size = sizes[kind] * count
            at = struct.unpack("<I", raw)[0] if size > 4 else ifd + 2 + 12 * i + 8
            if kind == _SHORT:
                tags[tag] = struct.unpack_from("<H", data, at)[0]
            elif kind == _LONG:
                tags[tag] = struct.unpack_from("<I", data, at)[0]
            elif kind == _RATIONAL:
                tags[tag] = struct.unpack_from("<II", data, at)
            else:
                tags[tag] = data[at : at + count].rstrip(b"\0").decode("ascii")
        dtype = {8: "<u1", 16: "<u2", 32: "<u4"}[tags[258]]
        w, h = tags[256], tags[257]
        pages.append(np.frombuffer(data, dtype=dtype, count=w * h, offset=tags[273]).reshape(h, w))
        tags0 = tags0 or tags
        (ifd,) = struct.unpack_from("<I", data, ifd + 2 + 12 * n)
    return np.stack(pages), tags0
