"""Mesh reading, quality distributions and conformity figures (ParaView's VTK + numpy)."""
import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersVerdict import vtkMeshQuality
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

# Fixed histogram bins, shared by every mesh so that distributions can be overlaid.
EDGE_RATIO_BINS = numpy.linspace(1.0, 6.0, 101)           # 0.05 wide; larger ratios: last bin
DIHEDRAL_BINS = numpy.linspace(0.0, 72.0, 145)            # 0.5 degrees wide
REGULAR_DIHEDRAL = 70.528779                                # the regular tetrahedron's angle


def read_grid(path):
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def tets_and_points(grid):
    points = vtk_to_numpy(grid.GetPoints().GetData()).astype(numpy.float64)
    corners = vtk_to_numpy(grid.GetCells().GetConnectivityArray()).reshape(-1, 4)
    return points, corners


def min_dihedral_angles(points, corners, chunk=1 << 20):
    """The true minimum dihedral angle (degrees) of every tet, from its four face normals:
    the dihedral angle at the edge between faces i and j is arccos(-n_i . n_j / |n_i||n_j|)
    for the outward (or all inward) normals n."""
    result = numpy.empty(len(corners))
    for start in range(0, len(corners), chunk):
        tets = corners[start:start + chunk]
        a, b, c, d = (points[tets[:, k]] for k in range(4))
        normals = [numpy.cross(c - b, d - b), numpy.cross(d - a, c - a),
                   numpy.cross(b - a, d - a), numpy.cross(c - a, b - a)]
        lengths = [numpy.linalg.norm(n, axis=1) for n in normals]
        for n, length in zip(normals, lengths):
            n /= numpy.where(length > 0, length, 1.0)[:, None]
        largest = numpy.full(len(tets), -1.0)
        for i in range(4):
            for j in range(i + 1, 4):
                numpy.maximum(largest, -numpy.einsum("ij,ij->i", normals[i], normals[j]),
                              out=largest)
        result[start:start + chunk] = numpy.degrees(numpy.arccos(numpy.clip(largest, -1, 1)))
    return result


def quality_arrays(grid, check=None):
    """EdgeRatio and the minimum dihedral angle (degrees) per tet. EdgeRatio: the mesh's own
    array when present, otherwise vtkMeshQuality's (the same Verdict metric). The minimum
    dihedral angle is computed here (min_dihedral_angles): the MinDihedralAngle arrays, from
    Verdict's tet minimum angle in ParaView 5.11's VTK, hold values up to about 86 degrees,
    above the regular tet's 70.53, which no minimum dihedral angle can reach. With a dict as
    `check`, the agreement of the file's MinDihedralAngle array with the computed angle is
    recorded in it."""
    data = grid.GetCellData()
    points, corners = tets_and_points(grid)
    angles = min_dihedral_angles(points, corners)
    if data.GetArray("EdgeRatio") is not None:
        edge_ratio = vtk_to_numpy(data.GetArray("EdgeRatio")).astype(numpy.float64)
    else:
        quality = vtkMeshQuality()
        quality.SetInputData(grid)
        quality.SetTetQualityMeasureToEdgeRatio()
        quality.Update()
        edge_ratio = vtk_to_numpy(
            quality.GetOutput().GetCellData().GetArray("Quality")).astype(numpy.float64)
    if check is not None and data.GetArray("MinDihedralAngle") is not None:
        array = vtk_to_numpy(data.GetArray("MinDihedralAngle")).astype(numpy.float64)
        differs = numpy.abs(array - angles) > 1e-6 * numpy.maximum(1.0, angles)
        check.update({
            "shareDiffering": float(numpy.count_nonzero(differs) / len(angles)),
            "arrayMax": float(array.max()), "computedMax": float(angles.max()),
            "arrayP1": float(numpy.percentile(array, 1)),
            "computedP1": float(numpy.percentile(angles, 1)),
            "arrayMin": float(array.min()), "computedMin": float(angles.min())})
    return edge_ratio, angles


def tet_volumes(points, corners):
    origin = points[corners[:, 0]]
    return numpy.abs(numpy.einsum(
        "ij,ij->i", points[corners[:, 1]] - origin,
        numpy.cross(points[corners[:, 2]] - origin, points[corners[:, 3]] - origin))) / 6.0


def histogram(values, bins):
    clipped = numpy.clip(values, bins[0], bins[-1])
    counts, _ = numpy.histogram(clipped, bins=bins)
    return [int(c) for c in counts]


def summarise(edge_ratio, min_dihedral):
    """Percentiles and histograms of both metrics (histograms: counts on the fixed bins)."""
    def percentiles(values):
        p = numpy.percentile(values, [0, 1, 5, 50, 95, 99, 100])
        return {"min": float(p[0]), "p1": float(p[1]), "p5": float(p[2]), "median": float(p[3]),
                "p95": float(p[4]), "p99": float(p[5]), "max": float(p[6]),
                "mean": float(values.mean())}
    return {
        "tets": int(len(edge_ratio)),
        "edgeRatio": percentiles(edge_ratio),
        "minDihedralAngle": percentiles(min_dihedral),
        "shareMinDihedralBelow10": float(numpy.count_nonzero(min_dihedral < 10.0) /
                                         max(1, len(min_dihedral))),
        # Verdict's edge ratio is 1e30 for a tet whose shortest edge is about 0: numerically
        # degenerate tets (their computed angles are meaningless)
        "degenerateTets": int(numpy.count_nonzero(edge_ratio > 1e6)),
        "edgeRatioHistogram": histogram(edge_ratio, EDGE_RATIO_BINS),
        "minDihedralHistogram": histogram(min_dihedral, DIHEDRAL_BINS),
    }


def mesh_quality(path, volume_bound=None):
    """Counts and quality summary of one .vtu; with a volume bound, the share of tets above it."""
    grid = read_grid(path)
    check = {}
    edge_ratio, min_dihedral = quality_arrays(grid, check)
    summary = summarise(edge_ratio, min_dihedral)
    if check:
        summary["minDihedralArrayCheck"] = check
    summary["points"] = int(grid.GetNumberOfPoints())
    points, corners = tets_and_points(grid)
    volumes = tet_volumes(points, corners)
    summary["totalVolume"] = float(volumes.sum())
    summary["meanVolume"] = float(volumes.mean())
    if volume_bound:
        summary["volumeBound"] = volume_bound
        summary["shareAboveBound"] = float(
            numpy.count_nonzero(volumes > volume_bound * (1 + 1e-9)) / len(volumes))
    return summary


def face_keys(corners):
    """The four faces of every tet as sorted corner triples, one row each."""
    faces = numpy.concatenate([corners[:, [0, 1, 2]], corners[:, [0, 1, 3]],
                               corners[:, [0, 2, 3]], corners[:, [1, 2, 3]]])
    faces.sort(axis=1)
    return faces


def face_multiplicity(corners):
    """Unique faces (sorted triples) and how many tets share each."""
    faces = face_keys(corners)
    order = numpy.lexsort((faces[:, 2], faces[:, 1], faces[:, 0]))
    faces = faces[order]
    new = numpy.ones(len(faces), dtype=bool)
    new[1:] = numpy.any(faces[1:] != faces[:-1], axis=1)
    starts = numpy.flatnonzero(new)
    counts = numpy.diff(numpy.append(starts, len(faces)))
    return faces[starts], counts


def triangle_areas(points, triangles):
    a = points[triangles[:, 0]]
    return 0.5 * numpy.linalg.norm(
        numpy.cross(points[triangles[:, 1]] - a, points[triangles[:, 2]] - a), axis=1)


def conformity(input_grid, output_grid):
    """Faces shared by one tet, by two, by more, and the area of the once-shared faces against
    the input's boundary area: in a conforming refinement of a mesh the once-shared faces are
    exactly the boundary, so any excess area is hanging (non-matching) interior faces."""
    in_points, in_corners = tets_and_points(input_grid)
    in_faces, in_counts = face_multiplicity(in_corners)
    boundary_area = float(triangle_areas(in_points, in_faces[in_counts == 1]).sum())
    points, corners = tets_and_points(output_grid)
    faces, counts = face_multiplicity(corners)
    once_area = float(triangle_areas(points, faces[counts == 1]).sum())
    figures = {
        "faces": int(len(faces)),
        "facesSharedOnce": int(numpy.count_nonzero(counts == 1)),
        "facesSharedTwice": int(numpy.count_nonzero(counts == 2)),
        "facesSharedMore": int(numpy.count_nonzero(counts > 2)),
        "inputBoundaryArea": boundary_area,
        "onceSharedFaceArea": once_area,
        "boundaryAreaChange": (once_area - boundary_area) / boundary_area,
    }
    figures["conforming"] = bool(figures["facesSharedMore"] == 0 and
                                 abs(figures["boundaryAreaChange"]) < 1e-9)
    return figures
