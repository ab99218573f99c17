# SPDX-License-Identifier: BSD-3-Clause
"""LoD Interpolation on the GPU: the vertex shader blends the detailed and the coarse places.

With Morph In Shader, LoD Interpolation outputs the detailed surface once, with each point's
place at t = 1 as the point array CoarsePoints (its tangents). The representation below draws
each vertex at mix(P, CoarsePoints, t), t one uniform: a frame is a render, with no pipeline
update. ParaView 5.11, builtin session (pvpython, pvbatch, the GUI's Python shell):
    pvpython morph_in_shader.py --plugin MeshSimplification.so --data Testing/Data --output out/
writes out/morph_in_shader_<t>.png for t = 0, 0.5 and 1.

What it relies on (VTK 9.2's vtkCompositePolyDataMapper2): the mapper passes a point array to
the vertex shader only as one of its own attributes, so CoarsePoints goes as the tangents
(SelectTangentArray; floats, three components), and the shift and scale ParaView applies to the
points by default is turned off, since it would not apply to the tangents. The normals stay the
detailed ones, so the surface is drawn flat (its facets' normals follow the morph). The uniform
lives in the client's shader property: in client-server mode write t into ShaderReplacements
instead (each new value compiles a shader once).
"""
import argparse
import json
import os

from paraview.simple import *  # noqa: F401,F403

# Replacements apply before VTK's own, so the blended place is declared at the top of main()
# and takes the name of the position VTK's lines use after it.
BLEND = json.dumps([
    {"type": "vertex", "original": "in vec4 vertexMC;", "replacement": "in vec4 vertexMC;\nin vec3 tangentMC;\n"},
    {"type": "vertex", "original": "//VTK::CustomBegin::Impl",
     "replacement": "vec4 morphedMC = vec4(mix(vertexMC.xyz, tangentMC, morphT), 1.0);\n#define vertexMC morphedMC\n"},
])


def morph_in_shader(display):
    """Sets display (of a LoD Interpolation with MorphInShader on) to blend in its vertex shader;
    returns the function that sets t (call it, then Render)."""
    display.SelectTangentArray = "CoarsePoints"
    display.CoordinateShiftScaleMethod = "Disable"
    display.Interpolation = "Flat"
    display.SuppressLOD = 1  # ParaView's decimated stand-in has no CoarsePoints
    actor = display.GetClientSideObject().GetActiveRepresentation().GetActor()
    uniforms = actor.GetShaderProperty().GetVertexCustomUniforms()
    uniforms.SetUniformf("morphT", 0.0)  # before the first render, which compiles the shader
    display.UseShaderReplacements = 1
    display.ShaderReplacements = BLEND
    return lambda t: uniforms.SetUniformf("morphT", float(t))


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--data", required=True)
    parser.add_argument("--output", required=True)
    args, _ = parser.parse_known_args()
    LoadPlugin(args.plugin, ns=globals())
    os.makedirs(args.output, exist_ok=True)
    cow = OFFReader(FileName=os.path.join(args.data, "cow.off"))
    coarse = ProgressiveMesh(Input=cow, TargetReduction=0.95, GenerateOriginalIds=1)
    morph = LoDInterpolation(Detailed=cow, Coarse=coarse, Correspondence="Exact", MorphInShader=1)
    view = CreateRenderView()
    view.OrientationAxesVisibility = 0
    set_t = morph_in_shader(Show(morph, view))
    view.ResetCamera()
    for t in (0.0, 0.5, 1.0):
        set_t(t)
        Render(view)
        SaveScreenshot(os.path.join(args.output, "morph_in_shader_%.1f.png" % t), view, ImageResolution=[600, 400])
