"""Renders a mode of a bladebench modes.vtu with ParaView (pvbatch) to a PNG and checks the picture:
the size asked and not blank (the mesh covers a good part of it in many colours). Usage:
pvbatch render_mode.py MODES_VTU ARRAY PNG WIDTH HEIGHT. Exit 1 with the reason when it is not."""
import sys

from paraview.simple import ColorBy, CreateView, SaveScreenshot, Show, WarpByVector, XMLUnstructuredGridReader
from paraview.vtk.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

vtu, array, png = sys.argv[1], sys.argv[2], sys.argv[3]
width, height = int(sys.argv[4]), int(sys.argv[5])
reader = XMLUnstructuredGridReader(FileName=[vtu])
warp = WarpByVector(Input=reader)
warp.Vectors = ["POINTS", array]
view = CreateView("RenderView")
view.ViewSize = [width, height]
display = Show(warp, view)
ColorBy(display, ("POINTS", array, "Magnitude"))
view.ResetCamera()
SaveScreenshot(png, view, ImageResolution=[width, height])

image = vtkPNGReader()
image.SetFileName(png)
image.Update()
w, h, _ = image.GetOutput().GetDimensions()
pixels = vtk_to_numpy(image.GetOutput().GetPointData().GetScalars())[:, :3]
background = pixels[0]
covered = (pixels != background).any(axis=1).mean()
colours = len({tuple(p) for p in pixels[::7]})
print(f"{png}: {w} x {h}, {covered:.1%} of the pixels drawn, {colours} colours")
if (w, h) != (width, height):
    sys.exit(f"the picture is {w} x {h}, asked {width} x {height}")
if covered < 0.05 or colours < 50:
    sys.exit(f"the picture is blank: {covered:.1%} of the pixels differ from the background, {colours} colours")
