"""LAS files for the tests, written and read with numpy from the ASPRS LAS
1.0-1.4 specification alone (independent of the package's C++ reader and
writer): ``write_las`` makes a file of any version and point format, with
extra bytes, VLRs and EVLRs; ``read_las`` reads one (uncompressed) with
structured dtypes, extra bytes named by their Extra Bytes VLR included."""

import struct

import numpy as np

HEADER_SIZES = {0: 227, 1: 227, 2: 227, 3: 235, 4: 375}
FORMATS_OF_VERSION = {0: (0, 1), 1: (0, 1), 2: (0, 1, 2, 3), 3: (0, 1, 2, 3, 4, 5), 4: tuple(range(11))}

_LEGACY = [("X", "<i4"), ("Y", "<i4"), ("Z", "<i4"), ("intensity", "<u2"), ("bits", "u1"),
           ("class_byte", "u1"), ("scan_angle_rank", "i1"), ("user_data", "u1"), ("point_source_id", "<u2")]
_EXTENDED = [("X", "<i4"), ("Y", "<i4"), ("Z", "<i4"), ("intensity", "<u2"), ("returns", "u1"),
             ("flag_bits", "u1"), ("classification", "u1"), ("user_data", "u1"), ("scan_angle", "<i2"),
             ("point_source_id", "<u2"), ("gps_time", "<f8")]
_GPS = [("gps_time", "<f8")]
_RGB = [("red", "<u2"), ("green", "<u2"), ("blue", "<u2")]
_WAVE = [("wave_packet", "V29")]
BASE_FIELDS = {
    0: _LEGACY, 1: _LEGACY + _GPS, 2: _LEGACY + _RGB, 3: _LEGACY + _GPS + _RGB,
    4: _LEGACY + _GPS + _WAVE, 5: _LEGACY + _GPS + _RGB + _WAVE,
    6: _EXTENDED, 7: _EXTENDED + _RGB, 8: _EXTENDED + _RGB + [("nir", "<u2")],
    9: _EXTENDED + _WAVE, 10: _EXTENDED + _RGB + [("nir", "<u2")] + _WAVE,
}
EXTRA_TYPES = {1: "u1", 2: "i1", 3: "<u2", 4: "<i2", 5: "<u4", 6: "<i4", 7: "<u8", 8: "<i8", 9: "<f4", 10: "<f8"}


def base_dtype(fmt):
    return np.dtype(BASE_FIELDS[fmt])


def sample_fields(n, fmt, seed=0):
    """The fields of n points: scaled integers and the fields LiDAR users filter on."""
    rng = np.random.default_rng(seed)
    k = np.arange(n)
    number = 1 + k % 3
    return {
        "X": rng.integers(-2**31, 2**31 - 1, n, dtype=np.int64).astype(np.int32),
        "Y": (k * 37 - 1000).astype(np.int32),
        "Z": rng.integers(-10**6, 10**6, n).astype(np.int32),
        "intensity": (13 * k % 65536).astype(np.uint16),
        "return_number": (1 + (k // 3) % number).astype(np.uint8),
        "number_of_returns": number.astype(np.uint8),
        "classification": (k % 20 if fmt <= 5 else (11 * k) % 256).astype(np.uint8),
        "synthetic": k % 4 == 0, "key_point": k % 6 == 0, "withheld": k % 5 == 0,
        "overlap": (k % 7 == 0) & (fmt >= 6),
        "gps_time": 1e5 + 0.25 * k, "red": k.astype(np.uint16), "green": (2 * k).astype(np.uint16),
        "blue": (65535 - k).astype(np.uint16),
    }


def write_las(path, minor, fmt, fields, scale=(0.01, 0.001, 0.0025), offset=(1000.5, -20.0, 3.0),
              extra=(), vlr_payload=b"", evlr=False, legacy_count_in_14=False):
    """Writes a LAS 1.``minor`` file of point format ``fmt`` with ``fields``
    (as ``sample_fields``) and extra bytes ``extra``: (name, dtype, values)
    described in an Extra Bytes VLR."""
    n = len(fields["X"])
    header_size = HEADER_SIZES[minor]
    dtype = np.dtype(BASE_FIELDS[fmt] + [(name, t) for name, t, _ in extra])
    records = np.zeros(n, dtype)
    for axis in "XYZ":
        records[axis] = fields[axis]
    records["intensity"] = fields["intensity"]
    records["point_source_id"] = np.arange(n) % 65536
    if fmt <= 5:
        records["bits"] = fields["return_number"] | (fields["number_of_returns"] << 3)
        records["class_byte"] = (fields["classification"] | (fields["synthetic"] << 5) | (fields["key_point"] << 6)
                                 | (fields["withheld"].astype(np.uint8) << 7))
    else:
        records["returns"] = fields["return_number"] | (fields["number_of_returns"] << 4)
        records["flag_bits"] = (fields["synthetic"].astype(np.uint8) | (fields["key_point"] << 1)
                                | (fields["withheld"] << 2) | (fields["overlap"] << 3))
        records["classification"] = fields["classification"]
    if "gps_time" in records.dtype.names:
        records["gps_time"] = fields["gps_time"]
    if "red" in records.dtype.names:
        for c in ("red", "green", "blue"):
            records[c] = fields[c]
    for name, _, values in extra:
        records[name] = values

    vlrs = b""
    count = 0
    if extra:
        descriptors = b""
        codes = {np.dtype(t): code for code, t in EXTRA_TYPES.items()}
        for name, t, _ in extra:
            descriptors += struct.pack("<2sBB32s4s24s24s24s24s24s32s", b"", codes[np.dtype(t)], 0,
                                       name.encode(), b"", b"", b"", b"", b"", b"", b"a test field")
        vlrs += struct.pack("<H16sHH32s", 0, b"LASF_Spec", 4, len(descriptors), b"extra bytes") + descriptors
        count += 1
    if vlr_payload:
        vlrs += struct.pack("<H16sHH32s", 0, b"someone", 7, len(vlr_payload), b"") + vlr_payload
        count += 1
    offset_to_points = header_size + len(vlrs)
    legacy_count = n if (fmt <= 5 or legacy_count_in_14) else 0
    xyz = [records[a].astype(np.float64) * s + o for a, s, o in zip("XYZ", scale, offset)]
    head = struct.pack("<4sHH16sBB32s32sHHHIIBHI5I3d3d6d", b"LASF", 0, 0, b"", 1, minor, b"las_spec.py", b"numpy",
                       1, 2024, header_size, offset_to_points, count, fmt, dtype.itemsize, legacy_count,
                       *([0] * 5), *scale, *offset,
                       *(v for c in xyz for v in ((c.max(), c.min()) if n else (0, 0))))
    assert len(head) == 227
    if minor >= 3:
        head += struct.pack("<Q", 0)
    if minor >= 4:
        head += struct.pack("<QIQ15Q", 0, 0, n, *([0] * 15))
    assert len(head) == header_size
    body = head + vlrs + records.tobytes()
    if evlr:
        assert minor == 4
        body = body[:235] + struct.pack("<QI", len(body), 1) + body[247:]
        body += struct.pack("<H16sHQ32s", 0, b"someone", 8, 100, b"an EVLR") + b"e" * 100
    with open(path, "wb") as f:
        f.write(body)
    return records


def read_las(path):
    """(header dict, records structured array, {extra name: array}, coordinates (N, 3) float64)."""
    with open(path, "rb") as f:
        data = f.read()
    assert data[:4] == b"LASF"
    minor = data[25]
    header_size, offset_to_points, vlr_count, fmt, record_length, legacy = struct.unpack_from("<HIIBHI", data, 94)
    scale = struct.unpack_from("<3d", data, 131)
    offset = struct.unpack_from("<3d", data, 155)
    count = struct.unpack_from("<Q", data, 247)[0] if minor >= 4 else legacy
    if minor >= 4 and count == 0:
        count = legacy
    extra = []
    at = header_size
    for _ in range(vlr_count):
        user, record_id, length = struct.unpack_from("<16sHH", data, at + 2)
        if user.rstrip(b"\0") == b"LASF_Spec" and record_id == 4:
            for d in range(length // 192):
                descriptor = data[at + 54 + 192 * d: at + 54 + 192 * (d + 1)]
                name = descriptor[4:36].split(b"\0")[0].decode()
                extra.append((name, EXTRA_TYPES[descriptor[2]]))
        at += 54 + length
    base = base_dtype(fmt)
    fields = list(BASE_FIELDS[fmt]) + extra
    used = np.dtype(fields).itemsize
    if used < record_length:
        fields.append(("undescribed_extra", f"V{record_length - used}"))
    records = np.frombuffer(data, np.dtype(fields), count=count, offset=offset_to_points)
    coordinates = np.column_stack([records[a].astype(np.float64) * s + o for a, s, o in zip("XYZ", scale, offset)])
    header = {"minor": minor, "format": fmt, "count": count, "scale": scale, "offset": offset,
              "record_length": record_length, "base_length": base.itemsize}
    return header, records, {name: records[name] for name, _ in extra}, coordinates


def filter_fields(records, fmt):
    """classification, return_number, number_of_returns, withheld, synthetic of the records."""
    if fmt <= 5:
        return {"classification": records["class_byte"] & 31, "return_number": records["bits"] & 7,
                "number_of_returns": (records["bits"] >> 3) & 7, "synthetic": (records["class_byte"] >> 5) & 1 == 1,
                "withheld": records["class_byte"] >> 7 == 1, "intensity": records["intensity"]}
    return {"classification": records["classification"], "return_number": records["returns"] & 15,
            "number_of_returns": records["returns"] >> 4, "synthetic": records["flag_bits"] & 1 == 1,
            "withheld": (records["flag_bits"] >> 2) & 1 == 1, "intensity": records["intensity"]}
