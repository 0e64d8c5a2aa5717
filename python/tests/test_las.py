"""LAS through the Python module: read_point_cloud on files written here
from the specification (tests/las_spec.py, numpy only), checked against
the independent numpy reader to the last bit; the filters and their
counts; Result.write_las read back by both readers; LAZ and bad files."""
import struct

import numpy as np
import pytest

import conformal_alpha_shapes as cas
from conftest import fibonacci_sphere
import las_spec


@pytest.mark.parametrize("minor", sorted(las_spec.FORMATS_OF_VERSION))
def test_every_version_and_format_reads_as_the_independent_reader(tmp_path, minor):
    for fmt in las_spec.FORMATS_OF_VERSION[minor]:
        for with_extra in (False, True):
            fields = las_spec.sample_fields(300, fmt, seed=fmt)
            extra = [("curvature", "<f4", np.linspace(-1, 1, 300).astype(np.float32)),
                     ("id", "<u8", np.arange(300, dtype=np.uint64))] if with_extra else ()
            path = tmp_path / f"v{minor}_f{fmt}_{int(with_extra)}.las"
            las_spec.write_las(path, minor, fmt, fields, extra=extra, vlr_payload=b"p" * 17 if with_extra else b"",
                               evlr=with_extra and minor == 4)
            header, records, extra_read, xyz = las_spec.read_las(path)
            cloud = cas.read_point_cloud(path)
            points, normals = cloud
            assert normals is None
            assert cloud.las["version"] == f"1.{minor}" and cloud.las["point_format"] == fmt
            # the same doubles, bit for bit, and the same scaled integers
            assert points.tobytes() == xyz.tobytes(), (minor, fmt)
            for axis in "XYZ":
                assert np.array_equal(cloud.fields[axis], records[axis])
            expected = las_spec.filter_fields(records, fmt)
            for name, values in expected.items():
                assert np.array_equal(cloud.fields[name], values), (minor, fmt, name)
            if "gps_time" in records.dtype.names:
                assert np.array_equal(cloud.fields["gps_time"], records["gps_time"])
            if "red" in records.dtype.names:
                assert np.array_equal(cloud.fields["blue"], records["blue"])
            if with_extra:
                assert header["record_length"] == header["base_length"] + 12
                assert np.array_equal(extra_read["id"], np.arange(300))


# Files as other LAS tools write them: (version minor, point format, CRS
# and where) with extra bytes (scaled ones, undescribed bytes after them),
# bytes between the VLRs and the points, a legacy count left 0 in LAS 1.4,
# wave packets in format 4.
AS_TOOLS_WRITE_THEM = [(1, 1, "geotiff"), (2, 1, "geotiff"), (2, 3, "geotiff"), (3, 1, "geotiff"), (3, 3, None),
                       (3, 4, "geotiff"), (4, 1, "geotiff"), (4, 3, "wkt"), (4, 4, "wkt"), (4, 6, "wkt"),
                       (4, 7, "wkt evlr"), (4, 8, "wkt")]


def _tool_file(path, minor, fmt, crs, points, with_extra, step=1e-6):
    """A file of ``points`` (at ``step``) as AS_TOOLS_WRITE_THEM describes it."""
    n = len(points)
    fields = las_spec.sample_fields(n, fmt, seed=fmt)
    for k, axis in enumerate("XYZ"):
        fields[axis] = np.round(points[:, k] / step).astype(np.int32)
    extra = [("reflectance", "<f4", np.linspace(-1, 1, n).astype(np.float32)),
             ("amplitude", "<u2", (np.arange(n) * 7 % 65536).astype(np.uint16), 0.01, 5.0),
             ("pulse_id", "<u8", np.arange(n, dtype=np.uint64) + 2**40)] if with_extra else ()
    las_spec.write_las(path, minor, fmt, fields, scale=(step,) * 3, offset=(0.0,) * 3, extra=extra,
                       crs=crs and crs.split()[0], crs_in_evlr=crs == "wkt evlr", padding=b"\0" * 13,
                       undescribed=3 if with_extra else 0, legacy_count_zero=minor == 4, evlr=minor == 4)


def test_files_as_other_tools_write_them_read_and_write_back_with_their_extra_bytes_and_crs(tmp_path):
    """The package reads each file's scaled integers and coordinates as the
    independent reader, to the last bit, with its extra bytes and CRS
    records; write_las carries them beside the curvature fields, as both
    readers see."""
    points, _ = fibonacci_sphere(400)
    points += (0.5, -0.25, 2.0)
    r = cas.multiscale_curvatures(points, radii=("4s",))
    names = ["outlier"] + [f"{v}_r4s" for v in ("nx", "ny", "nz", "H", "K", "k1", "k2", "d1x", "d1y", "d1z", "d2x",
                                                 "d2y", "d2z", "radius", "distance", "source")]
    for minor, fmt, crs in AS_TOOLS_WRITE_THEM:
        for with_extra in (False, True):
            case = (minor, fmt, crs, with_extra)
            path = tmp_path / f"v{minor}_f{fmt}_{int(with_extra)}.las"
            _tool_file(path, minor, fmt, crs, points, with_extra)
            header, records, extra, xyz = las_spec.read_las(path)
            cloud = cas.read_point_cloud(path)
            assert cloud.points.tobytes() == xyz.tobytes(), case
            for axis in "XYZ":
                assert np.array_equal(cloud.fields[axis], records[axis]), case
            base = header["base_length"]
            raw = np.frombuffer(path.read_bytes(), np.uint8, count=header["count"] * header["record_length"],
                                offset=header["offset_to_points"]).reshape(-1, header["record_length"])
            assert np.array_equal(cloud.fields["extra_bytes"], raw[:, base:]), case
            assert [(e["name"], e["descriptor"]) for e in cloud.las["extra_bytes"]][:len(header["descriptors"])] \
                == [(d["name"], d["bytes"]) for d in header["descriptors"]], case
            assert [(c["record_id"], c["data"]) for c in cloud.las["crs"]] == las_spec.crs_records(header), case
            if "nir" in records.dtype.names:
                assert np.array_equal(cloud.fields["nir"], records["nir"])

            out = tmp_path / f"out_v{minor}_f{fmt}_{int(with_extra)}.las"
            r.write_las(out, cloud)
            out_header, out_records, out_extra, out_xyz = las_spec.read_las(out)
            assert out_header["minor"] == 4 and out_header["format"] == {3: 7, 7: 7, 8: 8}.get(fmt, 6), case
            assert out_xyz.tobytes() == xyz.tobytes(), case
            assert np.array_equal(out_records["gps_time"], records["gps_time"]), case
            for name, values in las_spec.filter_fields(records, fmt).items():
                assert np.array_equal(las_spec.filter_fields(out_records, out_header["format"])[name], values)
            # the input's descriptors (the undescribed bytes as data type 0), then the curvature fields
            carried = [e["descriptor"] for e in cloud.las["extra_bytes"]]
            assert [d["bytes"] for d in out_header["descriptors"][:len(carried)]] == carried, case
            assert [d["name"] for d in out_header["descriptors"][len(carried):]] == names, case
            if with_extra:
                for name in ("reflectance", "amplitude", "pulse_id"):
                    assert np.array_equal(out_extra[name], extra[name]), (case, name)
                assert out_header["descriptors"][1]["scale"] == 0.01 and out_header["descriptors"][1]["offset"] == 5
                assert out_header["descriptors"][3]["data_type"] == 0 and out_header["descriptors"][3]["options"] == 3
            assert np.array_equal(out_extra["H_r4s"], r["r4s"].H.astype(np.float32)), case
            assert las_spec.crs_records(out_header) == las_spec.crs_records(header), case
            # the WKT bit: set with a WKT or without any CRS, clear when the CRS is GeoTIFF keys
            assert bool(out_header["global_encoding"] & 16) == (crs != "geotiff"), case
            back = cas.read_point_cloud(out)
            assert back.points.tobytes() == xyz.tobytes()
            assert np.array_equal(back.fields["extra_bytes"][:, :raw.shape[1] - base], raw[:, base:]), case
            assert back.las["crs"] == cloud.las["crs"], case


def test_an_input_field_named_as_a_curvature_field_is_replaced(tmp_path):
    """A curvatures.las read again: its own curvature fields are replaced by
    the new ones, its other extra bytes carried."""
    points, _ = fibonacci_sphere(300)
    path = tmp_path / "first.las"
    _tool_file(path, 4, 6, "wkt", points, True)
    cloud = cas.read_point_cloud(path)
    cas.multiscale_curvatures(cloud.points, radii=("4s",)).write_las(tmp_path / "second.las", cloud)
    again = cas.read_point_cloud(tmp_path / "second.las")
    r = cas.multiscale_curvatures(again.points, radii=("4s", "8s"))
    r.write_las(tmp_path / "third.las", again)
    header, _, extra, _ = las_spec.read_las(tmp_path / "third.las")
    names = [d["name"] for d in header["descriptors"]]
    assert names[:4] == ["reflectance", "amplitude", "pulse_id", "undescribed_extra_bytes"]
    assert names.count("outlier") == 1 and names.count("H_r4s") == 1 and "H_r8s" in names
    assert np.array_equal(extra["H_r8s"], r["r8s"].H.astype(np.float32))
    assert np.array_equal(extra["H_r4s"], r["r4s"].H.astype(np.float32))


def test_point_count_of_each_version(tmp_path):
    fields = las_spec.sample_fields(40, 1)
    las_spec.write_las(tmp_path / "legacy_in_14.las", 4, 1, fields)
    with open(tmp_path / "legacy_in_14.las", "r+b") as f:  # a writer that left the 64-bit count 0
        f.seek(247)
        f.write(struct.pack("<Q", 0))
    assert len(cas.read_point_cloud(tmp_path / "legacy_in_14.las").points) == 40
    fields = las_spec.sample_fields(40, 6)
    las_spec.write_las(tmp_path / "count_64.las", 4, 6, fields)
    assert len(cas.read_point_cloud(tmp_path / "count_64.las").points) == 40


def test_filters_and_their_counts(tmp_path):
    fields = las_spec.sample_fields(1000, 6)
    path = tmp_path / "filters.las"
    las_spec.write_las(path, 4, 6, fields)
    _, records, _, xyz = las_spec.read_las(path)
    f = las_spec.filter_fields(records, 6)
    by_class = np.isin(f["classification"], (2, 6, 11))
    not_withheld = by_class & ~f["withheld"]
    last = not_withheld & (f["return_number"] >= f["number_of_returns"])
    cloud = cas.read_point_cloud(path, classes=[2, 6, 11], drop_withheld=True, returns="last")
    assert cloud.counts == {"read": 1000, "classes": int(by_class.sum()), "withheld": int(not_withheld.sum()),
                            "returns": int(last.sum())}
    assert cloud.points.tobytes() == xyz[last].tobytes()
    assert np.array_equal(cloud.fields["classification"], f["classification"][last])
    assert cloud.summary == (f"{path}: LAS 1.4, point format 6, 1000 points; classes 2,6,11 kept {by_class.sum()}; "
                             f"without withheld points kept {not_withheld.sum()}; last returns kept {last.sum()}")
    first = cas.read_point_cloud(path, returns="first")
    assert len(first.points) == int((f["return_number"] <= 1).sum())
    assert len(cas.read_point_cloud(path, classes=11).points) == int((f["classification"] == 11).sum())
    with pytest.raises(ValueError, match="not a LAS class from 0 to 255: '256'"):
        cas.read_point_cloud(path, classes=[256])
    with pytest.raises(ValueError, match="unknown returns 'second'"):
        cas.read_point_cloud(path, returns="second")
    xyz_file = tmp_path / "points.xyz"
    np.savetxt(xyz_file, xyz[:10])
    with pytest.raises(ValueError, match="filter LAS input"):
        cas.read_point_cloud(xyz_file, classes=[2])


def _sphere_las(path, n=1500, fmt=7):
    """A LAS 1.4 file of a unit sphere sample, its points at 1e-6 steps."""
    points, _ = fibonacci_sphere(n)
    fields = las_spec.sample_fields(n, fmt)
    for k, axis in enumerate("XYZ"):
        fields[axis] = np.round(points[:, k] / 1e-6).astype(np.int32)
    las_spec.write_las(path, 4, fmt, fields, scale=(1e-6,) * 3, offset=(0.0,) * 3,
                       extra=[("reflectance", "<f4", np.ones(n, np.float32))], evlr=True)
    return fields


def test_write_las_keeps_the_fields_and_names_the_values(tmp_path):
    source = tmp_path / "sphere.las"
    _sphere_las(source)
    cloud = cas.read_point_cloud(source, drop_withheld=True)
    r = cas.multiscale_curvatures(cloud.points, radii=("auto", "4s"))
    out = tmp_path / "curvatures.las"
    r.write_las(out, cloud)
    header, records, extra, xyz = las_spec.read_las(out)
    assert header["minor"] == 4 and header["format"] == 7 and header["count"] == len(cloud.points)
    assert header["scale"] == (1e-6,) * 3
    assert xyz.tobytes() == cloud.points.tobytes()
    fields = las_spec.filter_fields(records, 7)
    for name in ("classification", "return_number", "number_of_returns", "intensity", "withheld"):
        assert np.array_equal(fields[name], cloud.fields[name]), name
    assert np.array_equal(records["gps_time"], cloud.fields["gps_time"])
    assert np.array_equal(records["red"], cloud.fields["red"])
    names = ["reflectance", "outlier"] + [f"{v}_{layer}" for layer in r.layers for v in
                                          ("nx", "ny", "nz", "H", "K", "k1", "k2", "d1x", "d1y", "d1z", "d2x",
                                           "d2y", "d2z", "radius", "distance", "source")]
    assert list(extra) == names
    assert np.array_equal(extra["reflectance"], np.ones(len(cloud.points), np.float32))
    for layer in r.layers:
        assert np.array_equal(extra[f"H_{layer}"], r[layer].H.astype(np.float32))
        assert np.array_equal(extra[f"d2y_{layer}"], r[layer].d2[:, 1].astype(np.float32))
        assert np.array_equal(extra[f"source_{layer}"], r[layer].source)
    assert np.array_equal(extra["outlier"], r.outlier.astype(np.uint8))
    # the package's reader: the same points and fields
    back = cas.read_point_cloud(out)
    assert back.points.tobytes() == cloud.points.tobytes()
    for name, values in cloud.fields.items():
        if name not in ("nir", "extra_bytes"):
            assert np.array_equal(back.fields[name], values), name
    assert np.array_equal(back.fields["extra_bytes"][:, :4], cloud.fields["extra_bytes"])
    assert back.las["version"] == "1.4" and back.las["point_format"] == 7


def test_write_las_of_other_points_chooses_a_scale(tmp_path):
    points, _ = fibonacci_sphere(600, radius=250.0)
    points += (512000.0, 4.1e6, 30.0)
    r = cas.multiscale_curvatures(points, radii=("4s",))
    out = tmp_path / "other.las"
    r.write_las(out)
    header, records, extra, xyz = las_spec.read_las(out)
    assert header["format"] == 6 and header["count"] == 600
    scale = np.array(header["scale"])
    assert (np.abs(xyz - points) <= 0.5 * scale * (1 + 1e-9)).all()
    assert np.array_equal(extra["H_r4s"], r["r4s"].H.astype(np.float32))
    with pytest.raises(ValueError, match="PointCloud of a LAS file"):
        r.write_las(out, cas.PointCloud({"points": points, "normals": None}))


def test_laz_and_bad_files_get_their_message(tmp_path):
    fields = las_spec.sample_fields(10, 6)
    good = tmp_path / "good.las"
    las_spec.write_las(good, 4, 6, fields)
    data = good.read_bytes()
    laz = tmp_path / "scan.laz"
    laz.write_bytes(data)
    with pytest.raises(ValueError, match=r"scan.laz: compressed LAS \(LAZ\) cannot be read without LASzip; "
                                         r"decompress it first, e.g. 'laszip -i x.laz -o x.las'"):
        cas.read_point_cloud(laz)
    cases = {
        "compressed.las": (data[:104] + bytes([0x86]) + data[105:], r"compressed LAS \(LAZ\)"),
        "truncated.las": (data[:-5], "the header announces 10 points of 30 bytes, the file holds 9"),
        "version.las": (data[:25] + bytes([7]) + data[26:], "unknown LAS version 1.7"),
        "format.las": (data[:104] + bytes([12]) + data[105:], "unknown LAS point data record format 12"),
        "inside.las": (data[:96] + struct.pack("<I", 100) + data[100:], r"offset to the point data \(100\) is inside"),
        "header.las": (data[:94] + struct.pack("<H", 300) + data[96:], "header size 300 is smaller than LAS 1.4's"),
        "scale.las": (data[:131] + struct.pack("<d", float("nan")) + data[139:], "X scale factor is not finite"),
        "short.las": (data[:50], "truncated LAS header"),
    }
    # the VLRs and EVLRs: one that runs into the points, one beyond the
    # file, an Extra Bytes VLR that does not fit the records
    las_spec.write_las(good, 4, 6, fields, extra=[("a", "<f4", np.zeros(10, np.float32))], crs="wkt",
                       crs_in_evlr=True)
    data = good.read_bytes()
    header, _, _, _ = las_spec.read_las(good)
    vlr_end = header["offset_to_points"]
    evlr_start = vlr_end + 10 * header["record_length"]
    cases.update({
        "vlr.las": (data[:100] + struct.pack("<I", 2) + data[104:], "VLR 2 of 2 runs into the point data"),
        "evlr.las": (data[:evlr_start + 20] + struct.pack("<Q", 10**6) + data[evlr_start + 28:],
                     "EVLR 1 of 1 is beyond the end of the file"),
        "evlr_start.las": (data[:235] + struct.pack("<Q", 400) + data[243:], r"the first EVLR \(at 400\) is not after"),
        "extra_type.las": (data[:375 + 54 + 2] + bytes([31]) + data[375 + 54 + 3:],
                           "extra-bytes field 1 of the Extra Bytes VLR has the unknown data type 31"),
        "extra_size.las": (data[:375 + 54 + 2] + bytes([10]) + data[375 + 54 + 3:],
                           "the Extra Bytes VLR describes 8 bytes per point or more, the records have 4"),
    })
    for name, (content, message) in cases.items():
        path = tmp_path / name
        path.write_bytes(content)
        with pytest.raises(ValueError, match=message) as e:
            cas.read_point_cloud(path)
        assert str(path) in str(e.value)
