"""LAS files for the tests, written and read with numpy from the ASPRS LAS
1.0-1.4 specification alone (LAS 1.4 R15 for the header, the VLRs and
EVLRs, the Extra Bytes descriptors and the waveform fields), independent of
the package's C++ reader and writer.

``write_las`` makes a file of any version and point format the way other
LAS tools write them: extra bytes described by an Extra Bytes VLR (scaled
ones too), a CRS as GeoTIFF keys (GeoKeyDirectoryTag 34735,
GeoDoubleParamsTag 34736, GeoAsciiParamsTag 34737, as LAS 1.0-1.3 writers
do) or as OGC WKT (record 2112, in a VLR or an EVLR, with the WKT bit of the
global encoding, as LAS 1.4 asks of point formats 6 to 10), bytes between
the VLRs and the point data (LAS 1.0's point data start signature, or a
writer's padding), a LAS 1.4 file of a legacy point format whose legacy
count is 0, and waveform packets (format 4, 5, 9, 10: the 29-byte
descriptor of each record, a Waveform Packet Descriptor VLR and the
waveform data after the points). ``read_las`` reads one (uncompressed) with
structured dtypes: the records, the extra bytes named by their descriptors,
the VLRs and EVLRs."""

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
# the wave packet: descriptor index, byte offset to its data, its size, the
# return point's location in it (picoseconds) and the parametric line x(t), y(t), z(t)
_WAVE = [("wave_descriptor", "u1"), ("wave_offset", "<u8"), ("wave_size", "<u4"), ("wave_location", "<f4"),
         ("wave_xt", "<f4"), ("wave_yt", "<f4"), ("wave_zt", "<f4")]
BASE_FIELDS = {
    0: _LEGACY, 1: _LEGACY + _GPS, 2: _LEGACY + _RGB, 3: _LEGACY + _GPS + _RGB,
    4: _LEGACY + _GPS + _WAVE, 5: _LEGACY + _GPS + _RGB + _WAVE,
    6: _EXTENDED, 7: _EXTENDED + _RGB, 8: _EXTENDED + _RGB + [("nir", "<u2")],
    9: _EXTENDED + _WAVE, 10: _EXTENDED + _RGB + [("nir", "<u2")] + _WAVE,
}
BASE_SIZES = {0: 20, 1: 28, 2: 26, 3: 34, 4: 57, 5: 63, 6: 30, 7: 36, 8: 38, 9: 59, 10: 67}
EXTRA_TYPES = {1: "u1", 2: "i1", 3: "<u2", 4: "<i2", 5: "<u4", 6: "<i4", 7: "<u8", 8: "<i8", 9: "<f4", 10: "<f8"}

# A CRS as GeoTIFF keys: WGS 84 / UTM zone 33N, metres, with its citation in
# the ASCII parameters and a double parameter (a vertical datum offset).
GEOKEY_DIRECTORY = struct.pack("<24H", 1, 1, 0, 5,
                               1024, 0, 1, 1,          # GTModelTypeGeoKey: projected
                               1025, 0, 1, 1,          # GTRasterTypeGeoKey: pixel is area
                               1026, 34737, 25, 0,     # GTCitationGeoKey: in the ASCII parameters
                               3072, 0, 1, 32633,      # ProjectedCSTypeGeoKey: EPSG 32633
                               4099, 0, 1, 9001)       # VerticalUnitsGeoKey: metre
GEOKEY_DOUBLES = struct.pack("<d", 0.0)
GEOKEY_ASCII = b"WGS 84 / UTM zone 33N|\0\0\0"
WKT = (b'PROJCS["WGS 84 / UTM zone 33N",GEOGCS["WGS 84",DATUM["WGS_1984",SPHEROID["WGS 84",6378137,'
       b'298.257223563,AUTHORITY["EPSG","7030"]],AUTHORITY["EPSG","6326"]],PRIMEM["Greenwich",0],'
       b'UNIT["degree",0.0174532925199433],AUTHORITY["EPSG","4326"]],PROJECTION["Transverse_Mercator"],'
       b'PARAMETER["latitude_of_origin",0],PARAMETER["central_meridian",15],PARAMETER["scale_factor",0.9996],'
       b'PARAMETER["false_easting",500000],PARAMETER["false_northing",0],UNIT["metre",1],'
       b'AUTHORITY["EPSG","32633"]]\0')
GEOTIFF_CRS = [(b"LASF_Projection", 34735, GEOKEY_DIRECTORY), (b"LASF_Projection", 34736, GEOKEY_DOUBLES),
               (b"LASF_Projection", 34737, GEOKEY_ASCII)]
WKT_CRS = [(b"LASF_Projection", 2112, WKT)]


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
        "blue": (65535 - k).astype(np.uint16), "nir": (3 * k % 65536).astype(np.uint16),
    }


def extra_descriptor(name, dtype, scale=None, offset=None, description=b"a test field", no_data=None):
    """The 192 bytes that describe an extra-bytes field of numpy type ``dtype``
    (data type 1 to 10), with the options scale, offset and no_data."""
    code = {np.dtype(t): c for c, t in EXTRA_TYPES.items()}[np.dtype(dtype)]
    options = (1 if no_data is not None else 0) | (8 if scale is not None else 0) | (16 if offset is not None else 0)
    d = bytearray(192)
    struct.pack_into("<BB32s", d, 2, code, options, name.encode())
    kind = "d" if np.dtype(dtype).kind == "f" else ("q" if np.dtype(dtype).kind == "i" else "Q")
    if no_data is not None:
        struct.pack_into("<" + kind, d, 40, no_data)
    if scale is not None:
        struct.pack_into("<d", d, 112, scale)
    if offset is not None:
        struct.pack_into("<d", d, 136, offset)
    struct.pack_into("<32s", d, 160, description)
    return bytes(d)


def vlr_bytes(user_id, record_id, payload, description=b""):
    return struct.pack("<H16sHH32s", 0, user_id, record_id, len(payload), description) + payload


def evlr_bytes(user_id, record_id, payload, description=b""):
    return struct.pack("<H16sHQ32s", 0, user_id, record_id, len(payload), description) + payload


def write_las(path, minor, fmt, fields, scale=(0.01, 0.001, 0.0025), offset=(1000.5, -20.0, 3.0),
              extra=(), vlr_payload=b"", evlr=False, legacy_count_zero=False, crs=None, crs_in_evlr=False,
              padding=b"", undescribed=0):
    """Writes a LAS 1.``minor`` file of point format ``fmt`` with ``fields``
    (as ``sample_fields``) and returns its records.

    extra: (name, dtype, values[, scale, offset]) fields described in an
        Extra Bytes VLR (``values``: the stored numbers, before any scale);
    undescribed: bytes after them that no descriptor names (0xEE);
    vlr_payload: a VLR of another writer; evlr: an EVLR of another writer (1.4);
    crs: "geotiff" (the three GeoTIFF records) or "wkt" (record 2112, with
        the WKT bit), in VLRs, or the WKT in an EVLR with ``crs_in_evlr``;
    padding: bytes between the VLRs and the point data (LAS 1.0 starts
        them with its point data start signature, 0xDD 0xCC, always);
    legacy_count_zero: in LAS 1.4, leave the legacy count of a legacy point
        format 0, as some writers do (by default it is filled, as the
        specification asks when the count fits).
    Formats with wave packets get a Waveform Packet Descriptor VLR, records
    pointing into the waveform data and that data after the points (in
    LAS 1.4 an EVLR, before 1.4 the record at "start of waveform data").
    """
    n = len(fields["X"])
    header_size = HEADER_SIZES[minor]
    dtype = np.dtype(BASE_FIELDS[fmt] + [(e[0], e[1]) for e in extra]
                     + ([("undescribed", f"V{undescribed}")] if undescribed else []))
    assert dtype.itemsize == BASE_SIZES[fmt] + sum(np.dtype(e[1]).itemsize for e in extra) + undescribed
    records = np.zeros(n, dtype)
    for axis in "XYZ":
        records[axis] = fields[axis]
    records["intensity"] = fields["intensity"]
    records["point_source_id"] = np.arange(n) % 65536
    records["user_data"] = np.arange(n) % 251
    if fmt <= 5:
        records["bits"] = fields["return_number"] | (fields["number_of_returns"] << 3)
        records["class_byte"] = (fields["classification"] | (fields["synthetic"] << 5) | (fields["key_point"] << 6)
                                 | (fields["withheld"].astype(np.uint8) << 7))
        records["scan_angle_rank"] = np.arange(n) % 181 - 90
    else:
        records["returns"] = fields["return_number"] | (fields["number_of_returns"] << 4)
        records["flag_bits"] = (fields["synthetic"].astype(np.uint8) | (fields["key_point"] << 1)
                                | (fields["withheld"] << 2) | (fields["overlap"] << 3))
        records["classification"] = fields["classification"]
        records["scan_angle"] = np.arange(n) % 30001 - 15000
    if "gps_time" in records.dtype.names:
        records["gps_time"] = fields["gps_time"]
    for c in ("red", "green", "blue", "nir"):
        if c in records.dtype.names:
            records[c] = fields[c]
    for e in extra:
        records[e[0]] = e[2]
    if undescribed:
        records["undescribed"] = np.frombuffer(b"\xee" * undescribed * n, f"V{undescribed}")
    waves = "wave_descriptor" in records.dtype.names
    samples = 8  # a waveform of 8 one-byte samples per point
    if waves:
        records["wave_descriptor"] = 1
        records["wave_offset"] = 60 * (minor >= 3) + samples * np.arange(n)  # from the start of the data record
        records["wave_size"] = samples
        records["wave_location"] = 1000.0
        records["wave_xt"], records["wave_yt"], records["wave_zt"] = 1e-4, -2e-4, 3e-3

    vlrs, count = b"", 0
    if extra:
        descriptors = b"".join(extra_descriptor(e[0], e[1], *e[3:]) for e in extra)
        vlrs += vlr_bytes(b"LASF_Spec", 4, descriptors, b"extra bytes")
        count += 1
    if waves:  # Waveform Packet Descriptor 1: 8 bits a sample, no compression, 8 samples, 1000 ps apart
        vlrs += vlr_bytes(b"LASF_Spec", 100 + 1, struct.pack("<BBIIdd", 8, 0, samples, 1000, 1.0, 0.0))
        count += 1
    crs_records = {"geotiff": GEOTIFF_CRS, "wkt": WKT_CRS, None: []}[crs]
    if not crs_in_evlr:
        for user, record_id, payload in crs_records:
            vlrs += vlr_bytes(user, record_id, payload, b"by las_spec.py")
            count += 1
    if vlr_payload:
        vlrs += vlr_bytes(b"someone", 7, vlr_payload)
        count += 1
    if minor == 0:
        padding = b"\xdd\xcc" + padding
    offset_to_points = header_size + len(vlrs) + len(padding)
    legacy_count = n if fmt <= 5 and not (minor == 4 and legacy_count_zero) else 0
    by_return = [int(np.sum(fields["return_number"] == r)) for r in range(1, 16)]
    legacy_by_return = by_return[:5] if legacy_count else [0] * 5
    global_encoding = (1 if minor >= 2 else 0) | (2 if waves else 0) | (16 if crs == "wkt" else 0)
    xyz = [records[a].astype(np.float64) * s + o for a, s, o in zip("XYZ", scale, offset)]
    head = struct.pack("<4sHH16sBB32s32sHHHIIBHI5I3d3d6d", b"LASF", 0, global_encoding, b"", 1, minor,
                       b"las_spec.py", b"numpy", 1, 2024, header_size, offset_to_points, count, fmt,
                       dtype.itemsize, legacy_count, *legacy_by_return, *scale, *offset,
                       *(v for c in xyz for v in ((c.max(), c.min()) if n else (0, 0))))
    assert len(head) == 227
    points_end = offset_to_points + n * dtype.itemsize
    tail, evlr_count = b"", 0
    if waves:
        data = bytes(range(256)) * (samples * n // 256 + 1)
        wave = (evlr_bytes(b"LASF_Spec", 65535, data[:samples * n], b"waveform data") if minor >= 3
                else data[:samples * n])
        tail += wave
        evlr_count += 1
    if minor >= 3:
        head += struct.pack("<Q", points_end if waves else 0)
    if crs_in_evlr:
        assert minor == 4
        for user, record_id, payload in crs_records:
            tail += evlr_bytes(user, record_id, payload, b"by las_spec.py")
            evlr_count += 1
    if evlr:
        assert minor == 4
        tail += evlr_bytes(b"someone", 8, b"e" * 100, b"an EVLR")
        evlr_count += 1
    if minor >= 4:
        head += struct.pack("<QIQ15Q", points_end if evlr_count else 0, evlr_count, n, *by_return)
    assert len(head) == header_size
    with open(path, "wb") as f:
        f.write(head + vlrs + padding + records.tobytes() + tail)
    return records


def _records(data, at, count, extended):
    """The (E)VLRs from ``at``: (user_id, record_id, description, payload) each."""
    out = []
    for _ in range(count):
        if extended:
            user, record_id, length, description = struct.unpack_from("<16sHQ32s", data, at + 2)
            head = 60
        else:
            user, record_id, length, description = struct.unpack_from("<16sHH32s", data, at + 2)
            head = 54
        out.append((user.rstrip(b"\0"), record_id, description.rstrip(b"\0"),
                    bytes(data[at + head:at + head + length])))
        at += head + length
    return out


def parse_descriptor(d):
    """The fields of an Extra Bytes descriptor (192 bytes)."""
    data_type, options = d[2], d[3]
    return {"name": d[4:36].split(b"\0")[0].decode(), "data_type": data_type, "options": options,
            "scale": struct.unpack_from("<d", d, 112)[0] if options & 8 else None,
            "offset": struct.unpack_from("<d", d, 136)[0] if options & 16 else None,
            "description": d[160:192].split(b"\0")[0], "bytes": d}


def read_las(path):
    """(header dict, records structured array, {extra name: array}, coordinates (N, 3) float64).

    The header dict holds the version, format, count, scale, offset,
    global encoding, record lengths, the VLRs and EVLRs (user_id, record_id,
    description, payload) and the Extra Bytes descriptors (parse_descriptor)."""
    data = memoryview(np.memmap(path, np.uint8, mode="r"))  # large files too
    assert data[:4] == b"LASF"
    minor = data[25]
    global_encoding = struct.unpack_from("<H", data, 6)[0]
    header_size, offset_to_points, vlr_count, fmt, record_length, legacy = struct.unpack_from("<HIIBHI", data, 94)
    scale = struct.unpack_from("<3d", data, 131)
    offset = struct.unpack_from("<3d", data, 155)
    count = struct.unpack_from("<Q", data, 247)[0] if minor >= 4 else legacy
    if minor >= 4 and count == 0:
        count = legacy
    vlrs = _records(data, header_size, vlr_count, False)
    evlrs = []
    if minor >= 4:
        start, evlr_count = struct.unpack_from("<QI", data, 235)
        evlrs = _records(data, start, evlr_count, True) if evlr_count else []
    descriptors = [parse_descriptor(payload[k:k + 192]) for user, record_id, _, payload in vlrs + evlrs
                   if user == b"LASF_Spec" and record_id == 4 for k in range(0, len(payload), 192)]
    extra = []
    for d in descriptors:
        extra.append((d["name"], EXTRA_TYPES[d["data_type"]] if d["data_type"] else f"V{d['options']}"))
    base = base_dtype(fmt)
    fields = list(BASE_FIELDS[fmt])
    names = set(name for name, _ in fields)
    for k, (name, t) in enumerate(extra):  # names as unique as numpy wants them
        fields.append((name if name not in names else f"{name}_{k}", t))
        names.add(fields[-1][0])
    used = np.dtype(fields).itemsize
    if used < record_length:
        fields.append(("undescribed_extra", f"V{record_length - used}"))
    records = np.frombuffer(data, np.dtype(fields), count=count, offset=offset_to_points)
    coordinates = np.column_stack([records[a].astype(np.float64) * s + o for a, s, o in zip("XYZ", scale, offset)])
    header = {"minor": minor, "format": fmt, "count": count, "legacy_count": legacy, "scale": scale,
              "offset": offset, "global_encoding": global_encoding, "record_length": record_length,
              "base_length": base.itemsize, "offset_to_points": offset_to_points, "vlrs": vlrs, "evlrs": evlrs,
              "descriptors": descriptors}
    return header, records, {name: records[fields[len(BASE_FIELDS[fmt]) + k][0]]
                             for k, (name, _) in enumerate(extra)}, coordinates


def crs_records(header):
    """The CRS records of a file read by read_las, VLRs then EVLRs: (record_id, payload) each."""
    return [(record_id, payload) for user, record_id, _, payload in header["vlrs"] + header["evlrs"]
            if user == b"LASF_Projection" and record_id in (34735, 34736, 34737, 2112)]


def filter_fields(records, fmt):
    """classification, return_number, number_of_returns, withheld, synthetic of the records."""
    if fmt <= 5:
        return {"classification": records["class_byte"] & 31, "return_number": records["bits"] & 7,
                "number_of_returns": (records["bits"] >> 3) & 7, "synthetic": (records["class_byte"] >> 5) & 1 == 1,
                "withheld": records["class_byte"] >> 7 == 1, "intensity": records["intensity"]}
    return {"classification": records["classification"], "return_number": records["returns"] & 15,
            "number_of_returns": records["returns"] >> 4, "synthetic": records["flag_bits"] & 1 == 1,
            "withheld": (records["flag_bits"] >> 2) & 1 == 1, "intensity": records["intensity"]}
