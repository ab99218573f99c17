# SPDX-License-Identifier: BSD-3-Clause
"""Texture Baking under MPI (mpiexec -n 2 pvbatch): a sphere coloured by its Elevation, each
process with its piece, simplified and baked. Every process bakes its own triangles' squares of
one atlas of the whole surface, and the texture is merged, so the render (each piece drawn with
the texture of its process, whichever process delivers the texture's request) shows the
elevation's colours everywhere: red at the top, green in the middle, blue at the bottom. With a
texture per process, the pieces showed each other's texels; with the texture's request passed on
(one piece), every process baked the whole sphere for an atlas the pieces' coordinates did not
match. The field data counts are the whole texture's: no empty texel, every square found from
the record of where points came from."""
import os

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403 (the pvpython idiom)

from plugintest import arguments, check, failures, finish, render_textured

args = arguments("--temp")
LoadPlugin(args.plugin, ns=globals())

sphere = Triangulate(Input=Elevation(Input=Sphere(ThetaResolution=64, PhiResolution=64),
                                     LowPoint=[0, 0, -0.5], HighPoint=[0, 0, 0.5]))
simplified = OctreeVertexClustering(Input=sphere, TargetReduction=0.95, GenerateOriginalIds=1)
bake = TextureBaking(Simplified=simplified, Original=sphere, TextureSize="512")
bake.UpdatePipeline()
texture = servermanager.Fetch(bake, idx=1)
counts = {name: texture.GetFieldData().GetArray(name).GetValue(0) for name in ("EmptyTexels", "ExactSearches")}
check(counts == {"EmptyTexels": 0, "ExactSearches": 0}, "no empty texel, no square searched for: %s" % counts)

image = render_textured(bake, os.path.join(args.temp or ".", "TestTextureBakingPieces.png"))
# Down the sphere's middle column, and across its equator: the colour of the elevation there.
for x, y, hue in [(150, 215, "red"), (150, 150, "green"), (150, 85, "blue"), (100, 150, "green"), (200, 150, "green")]:
    r, g, b = [image.GetScalarComponentAsDouble(x, y, 0, c) for c in range(3)]
    strongest = max((r, "red"), (g, "green"), (b, "blue"))[1]
    check(strongest == hue, "pixel (%d, %d) %s, the elevation's %s" % (x, y, (r, g, b), hue))
# pvbatch ends MPI when the script returns; exiting from one process aborts the others, which
# is only right for a failure.
if failures:
    finish()
print("1 passed, 0 failed")
