"""The XDMF sidecars read back by VTK's own XDMF reader (the one ParaView uses), on a real run.

A tiny run (H/8, 60 s, three bulk snapshots) is written by the solver; VTK then reads RUN.xdmf
and RUN.interface.xdmf, and every time step, the mesh and every field it delivers must equal
the datasets of RUN.h5 exactly (the sidecars hold no data, only pointers: anything but equality
is a wrong pointer, shape or type). The reader is VTK's vtkXdmfReader (XDMF 2 library, what ParaView's
"XDMF Reader" is): Debian's python3-vtk9 is built without it, so it comes from ParaView's VTK
(python3-paraview, scripts/setup.sh). Skipped without it or without the solver binary (a failure
under CI=true).
"""

import h5py
import numpy as np
import pytest

from solver_runs import missing, tiny_run

SNAPSHOT_TIMES = [0.0, 20.0, 45.5]
INTERFACE_FIELDS = ("slip_velocity", "slip", "opening", "normal_traction", "tangential_traction", "state")


@pytest.fixture(scope="module")
def vtk():
    """(vtkXdmfReader class, vtk_to_numpy, TIME_STEPS key) of ParaView's VTK."""
    try:
        from vtkmodules.util.numpy_support import vtk_to_numpy
        from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline
        from vtkmodules.vtkIOXdmf2 import vtkXdmfReader
    except ImportError:
        missing("no vtkXdmfReader: Debian's python3-vtk9 is built without XDMF; its reader comes "
                 "with ParaView's VTK (apt-get install python3-paraview)")
    return vtkXdmfReader, vtk_to_numpy, vtkStreamingDemandDrivenPipeline.TIME_STEPS()


@pytest.fixture(scope="module")
def run_file(tmp_path_factory):
    return tiny_run(tmp_path_factory.mktemp("xdmf"),
                    {"interface_stride": 4, "snapshot_times": SNAPSHOT_TIMES, "progress": "never"})


def read_all_times(vtk, path):
    """[(t, data set)] of every time step VTK's XDMF reader announces for `path`."""
    reader_class, _, time_steps = vtk
    reader = reader_class()
    reader.SetFileName(str(path))
    reader.UpdateInformation()
    times = reader.GetOutputInformation(0).Get(time_steps)
    assert times, f"{path}: VTK found no time steps"
    steps = []
    for t in times:
        reader.UpdateTimeStep(t)
        output = reader.GetOutputDataObject(0)
        copy = output.NewInstance()
        copy.DeepCopy(output)
        steps.append((t, copy))
    return steps


def test_bulk_sidecar_reads_back_as_the_snapshots(vtk, run_file):
    _, vtk_to_numpy, _ = vtk
    steps = read_all_times(vtk, run_file.with_suffix(".xdmf"))
    with h5py.File(run_file, "r") as f:
        group = f["snapshots"]
        coordinates, connectivity = group["coordinates"][()], group["connectivity"][()]
        snapshot_ids = sorted(k for k in group if k.isdigit())
        assert [t for t, _ in steps] == [group[k].attrs["t"] for k in snapshot_ids]
        assert len(steps) == len(SNAPSHOT_TIMES)
        for (t, grid), key in zip(steps, snapshot_ids):
            assert grid.GetClassName() == "vtkUnstructuredGrid"
            points = vtk_to_numpy(grid.GetPoints().GetData())
            np.testing.assert_array_equal(points[:, :2], coordinates)
            np.testing.assert_array_equal(points[:, 2], 0.0)
            cells = vtk_to_numpy(grid.GetCells().GetConnectivityArray()).reshape(-1, 4)
            np.testing.assert_array_equal(cells, connectivity)
            assert set(vtk_to_numpy(grid.GetCellTypesArray())) == {9}  # VTK_QUAD
            for field in ("displacement", "velocity"):
                values = vtk_to_numpy(grid.GetPointData().GetArray(field))
                np.testing.assert_array_equal(values[:, :2], group[key][field][()], err_msg=f"{key} {field}")
            # The run moves: the fields are not all zero, so equality above compares something.
            assert np.abs(group[key]["displacement"][()]).max() > 0


def test_interface_sidecar_reads_back_as_the_interface_series(vtk, run_file):
    _, vtk_to_numpy, _ = vtk
    path = run_file.parent / "run.interface.xdmf"
    steps = read_all_times(vtk, path)
    with h5py.File(run_file, "r") as f:
        interface = {name: f["interface"][name][()] for name in ("x", "t", *INTERFACE_FIELDS)}
    assert len(steps) == interface["t"].size > 3
    np.testing.assert_array_equal([t for t, _ in steps], interface["t"])
    for k, (t, grid) in enumerate(steps):
        assert grid.GetNumberOfPoints() == interface["x"].size
        points = np.array([grid.GetPoint(i) for i in range(grid.GetNumberOfPoints())])
        np.testing.assert_array_equal(points[:, 0], interface["x"])
        np.testing.assert_array_equal(points[:, 1:], 0.0)
        for field in INTERFACE_FIELDS:
            array = grid.GetPointData().GetArray(field)
            assert array is not None, f"step {k}: no {field}"
            np.testing.assert_array_equal(vtk_to_numpy(array), interface[field][k], err_msg=f"step {k} {field}")
    # The tractions are not zero, so the comparison is not one of zeros. (The tiny run sticks throughout:
    # its slip velocity is exactly zero, as the stick phase in wavenumbers holds the contact exactly.)
    assert np.abs(interface["normal_traction"]).max() > 0 and np.abs(interface["tangential_traction"]).max() > 0


@pytest.fixture(scope="module")
def substrate_run_file(tmp_path_factory):
    """A tiny run with a deformable substrate (docs/substrate.md): format 3, /substrate_snapshots."""
    import json
    import subprocess

    from solver_runs import solver_or_skip
    folder = tmp_path_factory.mktemp("xdmf_substrate")
    config = {"mesh": {"elements_per_H": 8}, "time": {"t_end": 60.0},
              "substrate": {"E": 3000.0, "nu": 0.3, "rho": 2000.0, "H": 12.5},
              "output": {"interface_stride": 4, "snapshot_times": SNAPSHOT_TIMES, "progress": "never"}}
    (folder / "config.json").write_text(json.dumps(config))
    subprocess.run([str(solver_or_skip()), "run", str(folder / "config.json"), "-o", str(folder / "run.h5")],
                   check=True, capture_output=True, timeout=300)
    return folder / "run.h5"


def test_bulk_sidecar_of_a_substrate_run_holds_both_bodies(vtk, substrate_run_file):
    """Each time is a spatial collection (a multiblock for VTK): the layer, then the substrate."""
    _, vtk_to_numpy, _ = vtk
    steps = read_all_times(vtk, substrate_run_file.with_suffix(".xdmf"))
    assert len(steps) == len(SNAPSHOT_TIMES)
    with h5py.File(substrate_run_file, "r") as f:
        assert f.attrs["format_version"] == 3
        for (t, blocks), k in zip(steps, range(len(SNAPSHOT_TIMES))):
            assert blocks.GetNumberOfBlocks() == 2, blocks.GetClassName()
            key = f"{k:04d}"
            for b, group_name in enumerate(("snapshots", "substrate_snapshots")):
                grid, group = blocks.GetBlock(b), f[group_name]
                points = vtk_to_numpy(grid.GetPoints().GetData())
                np.testing.assert_array_equal(points[:, :2], group["coordinates"][()])
                for field in ("displacement", "velocity"):
                    values = vtk_to_numpy(grid.GetPointData().GetArray(field))
                    np.testing.assert_array_equal(values[:, :2], group[key][field][()], err_msg=f"{group_name} {key}")
            assert f["substrate_snapshots"]["coordinates"][()][:, 1].min() == -12.5
            assert np.abs(f["substrate_snapshots"][key]["displacement"][()]).max() > 0
