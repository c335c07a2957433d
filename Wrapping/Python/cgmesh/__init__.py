"""Python access to the VTK module CGMesh::Filters, wrapped against ParaView's VTK.

    from cgmesh import vtkCoarseGrainedMeshAdaptation

works in /usr/bin/python3 (with python3-paraview installed) and in pvbatch, once the directory
holding this package is on PYTHONPATH.
"""
# The filter derives from vtkUnstructuredGridAlgorithm: load the VTK modules that define its base
# classes first, so that the wrapped class finds them registered.
from vtkmodules import vtkCommonDataModel, vtkCommonExecutionModel  # noqa: F401

from .cgmeshFilters import vtkCoarseGrainedMeshAdaptation

__all__ = ["vtkCoarseGrainedMeshAdaptation"]
