# SPDX-License-Identifier: BSD-3-Clause
"""Run by the ParaView GUI (paraview --script=... --exit): load the plugin, simplify the cow with
each filter, and write the triangle counts ("octree volume parallel progressive-at-90 %
progressive-at-50 % builds", the progressive mesh's second level from its first build), then
Texture Baking's six flags (1 where it holds: the surface shown has the filter's texture, a
Texture proxy fed by its second output in the textures group that the Texture menu lists; it is
coloured by Solid Color; the render shows the baked elevation, red above and blue below; the
texture is renamed with the filter; a state saved and loaded again has that one texture, on the
surface; deleting the filter unregisters its texture, also after the state was loaded) - or the error - to the file
MESHSIMPLIFICATION_MARKER names, for Testing/GUI/TestParaViewGUI.cmake to check."""
import os
import traceback

marker = os.environ["MESHSIMPLIFICATION_MARKER"]


def baked_texture_flags():
    """Texture Baking of a sphere coloured by its Elevation, shown in the GUI: the six flags.
    (The plugin's filters are this module's names, as LoadPlugin put them.)"""
    from paraview import servermanager
    from vtkmodules.vtkIOImage import vtkPNGReader
    sphere = Triangulate(Input=Elevation(Input=Sphere(ThetaResolution=64, PhiResolution=64),
                                         LowPoint=[0, 0, -0.5], HighPoint=[0, 0, 0.5]))
    bake = TextureBaking(Simplified=OctreeVertexClustering(Input=sphere, TargetReduction=0.95, GenerateOriginalIds=1),
                         Original=sphere, TextureSize="512")
    view = GetActiveViewOrCreate("RenderView")
    for shown in view.Representations:
        shown.Visibility = 0
    display = Show(bake, view)
    texture = display.Texture
    textures = servermanager.ProxyManager().GetProxiesInGroup("textures").values()
    textured = texture is not None and texture.Input is not None and texture.Input.Port == 1 and \
        texture.Input.GetXMLName() == "TextureBaking" and texture in textures
    solid = display.ColorArrayName[1] == ""
    view.OrientationAxesVisibility = 0
    view.CameraPosition = [0, -3, 0]
    view.CameraFocalPoint = [0, 0, 0]
    view.CameraViewUp = [0, 0, 1]
    view.ResetCamera()
    shot = marker + ".png"
    SaveScreenshot(shot, view, ImageResolution=[300, 300])
    reader = vtkPNGReader()
    reader.SetFileName(shot)
    reader.Update()
    top = [reader.GetOutput().GetScalarComponentAsDouble(150, 200, 0, c) for c in range(3)]
    bottom = [reader.GetOutput().GetScalarComponentAsDouble(150, 100, 0, c) for c in range(3)]
    rendered = top[0] > top[2] + 40 and bottom[2] > bottom[0] + 40

    def texture_names():
        return sorted(name for name, _ in servermanager.ProxyManager().GetProxiesInGroup("textures").keys())

    RenameSource("Renamed", bake)
    renamed = texture_names() == ["Renamed Texture"]
    state = marker + ".pvsm"
    SaveState(state)
    Delete(bake)
    removed = texture_names() == []
    LoadState(state)
    reloaded = FindSource("Renamed")
    kept = texture_names() == ["Renamed Texture"] and GetDisplayProperties(reloaded, view).Texture is not None
    Delete(reloaded)
    removed = removed and texture_names() == []
    return " ".join(str(int(flag)) for flag in (textured, solid, rendered, renamed, kept, removed))


try:
    from paraview.simple import *  # noqa: F401,F403

    LoadPlugin(os.environ["MESHSIMPLIFICATION_PLUGIN"], ns=globals())
    cow = OFFReader(FileName=os.environ["MESHSIMPLIFICATION_COW"])
    simplified = OctreeVertexClustering(Input=cow, TargetReduction=0.9)
    simplified.UpdatePipeline()
    Show(simplified)
    collapsed = VolumeTriangleCollapse(Input=cow, TargetReduction=0.9)
    collapsed.UpdatePipeline()
    Show(collapsed)
    decimated = ParallelDecimation(Input=cow, TargetReduction=0.9)
    decimated.UpdatePipeline()
    Show(decimated)
    levels = ProgressiveMesh(Input=cow, TargetReduction=0.9)
    Show(levels)
    Render()
    coarse = levels.GetDataInformation().GetNumberOfCells()
    levels.TargetReduction = 0.5  # as the slider does
    Render()
    fine = levels.GetDataInformation().GetNumberOfCells()
    levels.UpdatePropertyInformation()
    result = "%d %d %d %d %d %d\n" % (simplified.GetDataInformation().GetNumberOfCells(),
                                       collapsed.GetDataInformation().GetNumberOfCells(),
                                       decimated.GetDataInformation().GetNumberOfCells(),
                                       coarse, fine, levels.GetPropertyValue("NumberOfBuilds"))
    result = result.strip() + " " + baked_texture_flags() + "\n"
except Exception:
    result = "error\n" + traceback.format_exc()
with open(marker, "w") as out:
    out.write(result)
