# SPDX-License-Identifier: BSD-3-Clause
"""The plugin's Texture Baking (pvpython): a sphere coloured by its Elevation, simplified by 95 %
and baked. Its defaults; the first output carries texture coordinates on the simplified
triangles, the second is the texture; shown through a Texture proxy fed by the second output,
the render has the elevation's colours from red at the top to blue at the bottom; a lookup
table from the session (Grayscale) gives grey texels. A multiblock of two spheres bakes one
texture for both blocks, and shows it on both."""
import os

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403 (the pvpython idiom)

from plugintest import arguments, check, finish, render_textured

args = arguments("--temp")

LoadPlugin(args.plugin, ns=globals())

sphere = Triangulate(Input=Elevation(Input=Sphere(ThetaResolution=64, PhiResolution=64),
                                     LowPoint=[0, 0, -0.5], HighPoint=[0, 0, 0.5]))
simplified = OctreeVertexClustering(Input=sphere, TargetReduction=0.95, GenerateOriginalIds=1)
bake = TextureBaking(Simplified=simplified, Original=sphere)
check(bake.TextureSize == "2048" and bake.GutterWidth == 2 and bake.MaximumDistance == 0.05 and
      list(bake.Colors) == ["POINTS", "None"], "defaults")
bake.TextureSize = "512"
bake.UpdatePipeline()
surface = servermanager.Fetch(bake)
check(surface.GetNumberOfPolys() == simplified.GetDataInformation().GetNumberOfCells(),
      "the simplified triangles, all of them")
tcoords = surface.GetPointData().GetTCoords()
check(tcoords is not None and tcoords.GetNumberOfComponents() == 2 and
      0.0 <= tcoords.GetRange(0)[0] and tcoords.GetRange(0)[1] <= 1.0, "texture coordinates in [0, 1]")
texture = servermanager.Fetch(bake, idx=1)
check(texture.GetDimensions() == (512, 512, 1) and texture.GetPointData().GetArray("BakedTexture") is not None,
      "a 512 x 512 texture")

# Shown textured: a Texture proxy fed by the second output, scalar colouring off.
shot = os.path.join(args.temp or ".", "TestTextureBakingPlugin.png")


def check_red_above_blue(image, x, what):
    """The render's column x: red above the middle, blue below."""
    top = [image.GetScalarComponentAsDouble(x, 200, 0, c) for c in range(3)]
    bottom = [image.GetScalarComponentAsDouble(x, 100, 0, c) for c in range(3)]
    check(top[0] > top[2] + 40 and bottom[2] > bottom[0] + 40,
          "%s: red above and blue below (top %s, bottom %s)" % (what, top, bottom))


check_red_above_blue(render_textured(bake, shot), 150, "rendered")

# A lookup table of the session's: Grayscale gives grey texels.
table = GetColorTransferFunction("Elevation")
table.ApplyPreset("Grayscale", True)
bake.LookupTable = table
bake.UpdatePipeline()
texels = servermanager.Fetch(bake, idx=1).GetPointData().GetArray("BakedTexture")
grey = [texels.GetTuple3(i) for i in range(0, texels.GetNumberOfTuples(), 997)]
check(all(abs(r - g) <= 1 and abs(g - b) <= 1 for r, g, b in grey) and any(r > 0 for r, _, _ in grey),
      "grey texels through the session's Grayscale table")

# A multiblock of two spheres: one texture for both, and the output keeps the two blocks.
pair = Triangulate(Input=Elevation(Input=GroupDatasets(Input=[Sphere(Center=[-0.6, 0, 0], ThetaResolution=64, PhiResolution=64),
                                                              Sphere(Center=[0.6, 0, 0], ThetaResolution=64, PhiResolution=64)]),
                                   LowPoint=[0, 0, -0.5], HighPoint=[0, 0, 0.5]))
pairBake = TextureBaking(Simplified=OctreeVertexClustering(Input=pair, TargetReduction=0.95, GenerateOriginalIds=1),
                         Original=pair, TextureSize="512")
pairBake.UpdatePipeline()
blocks = servermanager.Fetch(pairBake)
check(blocks.IsA("vtkMultiBlockDataSet") and blocks.GetNumberOfBlocks() == 2 and
      all(blocks.GetBlock(b).GetPointData().GetTCoords() is not None for b in range(2)), "two blocks with texture coordinates")
image = render_textured(pairBake, shot)
check_red_above_blue(image, 80, "the left block")
check_red_above_blue(image, 220, "the right block")
finish()
