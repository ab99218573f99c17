# SPDX-License-Identifier: BSD-3-Clause
"""Texture Baking in ParaView: a coloured surface simplified by 99 %, its colours kept in a texture.

Texture Baking's first output is the simplified surface with texture coordinates, its second the
texture (an image). ParaView 5.11 shows the texture through a Texture proxy fed by that second
output, set as the representation's Texture, with scalar colouring off (in the GUI: colour by
Solid Color; the Texture menu under Lighting lists textures made in Python). pvpython or pvbatch:
    pvpython bake_texture.py --plugin MeshSimplification.so --input colored.vtp --output out/
writes out/bake_texture.png (left: the simplification's own vertex colours; right: the baked
texture) and out/baked.obj with its .mtl and .png. Without --input, a sphere coloured by its elevation is used.
"""
import argparse
import os

from paraview.simple import *  # noqa: F401,F403

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--input", help="a surface with colours (an unsigned-char RGB point array, or scalars)")
parser.add_argument("--output", default=".")
parser.add_argument("--reduction", type=float, default=0.99)
args = parser.parse_args()
LoadPlugin(args.plugin, ns=globals())
os.makedirs(args.output, exist_ok=True)

if args.input:
    original = OpenDataFile(args.input)
else:
    original = Elevation(Input=Sphere(ThetaResolution=256, PhiResolution=256),
                         LowPoint=[0, 0, -0.5], HighPoint=[0, 0, 0.5])
# Generate Original Ids lets the bake start each texel's search where the points came from.
simplified = VolumeTriangleCollapse(Input=original, TargetReduction=args.reduction, GenerateOriginalIds=1)
baked = TextureBaking(Simplified=simplified, Original=original, TextureSize="2048")

original.UpdatePipeline()
bounds = original.GetDataInformation().GetBounds()
width = bounds[1] - bounds[0]
view = CreateRenderView()
view.ViewSize = [1000, 500]
view.OrientationAxesVisibility = 0
# Left: the simplified surface with its vertex colours (the original's active scalars, carried,
# through the session's colour map, which the bake then uses too).
plain = Show(simplified, view)
if plain.ColorArrayName[1]:
    baked.LookupTable = GetColorTransferFunction(plain.ColorArrayName[1])
plain.Position = [-0.6 * width, 0, 0]
# Right: the same triangles textured.
textured = Show(OutputPort(baked, 0), view)
ColorBy(textured, None)
texture = servermanager.rendering.Texture()
texture.Input = OutputPort(baked, 1)
textured.Texture = texture
textured.Position = [0.6 * width, 0, 0]
view.CameraPosition = [0, -4 * width, 0]
view.CameraFocalPoint = [0, 0, 0]
view.CameraViewUp = [0, 0, 1]
view.ResetCamera()
Render(view)
SaveScreenshot(os.path.join(args.output, "bake_texture.png"), view, ImageResolution=[1000, 500])

# The textured surface as OBJ + MTL + PNG, the MTL naming the PNG by its file name (given the
# texture on its second input instead, the OBJ writer names it by its full path).
from vtkmodules.vtkIOGeometry import vtkOBJWriter  # noqa: E402
from vtkmodules.vtkIOImage import vtkPNGWriter  # noqa: E402

png = vtkPNGWriter()
png.SetInputData(servermanager.Fetch(baked, idx=1))
png.SetFileName(os.path.join(args.output, "baked.png"))
png.Write()
writer = vtkOBJWriter()
writer.SetInputData(servermanager.Fetch(baked))
writer.SetTextureFileName("baked.png")
writer.SetFileName(os.path.join(args.output, "baked.obj"))
writer.Write()
Delete(view)
del view
