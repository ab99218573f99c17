// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   pqTextureBakingTextures
 * @brief   shows Texture Baking's surface textured in the ParaView GUI: each Texture Baking gets
 *          a texture fed by its second output, named after it
 *
 * ParaView 5.11's Texture menu (Properties, Lighting) lists the proxies of the "textures" group
 * and image files; a filter's image output is neither. This auto-start component of the
 * plugin's GUI side gives a Texture Baking, when its first output is first shown, a Texture
 * proxy fed by its second output, registered as "<name> Texture" (so it is in that menu for any
 * representation), and sets it on that representation, coloured by Solid Color (scalar colours
 * would tint the texture). A representation that has a texture already (from a state file)
 * keeps it, and a texture fed by the filter is taken rather than made twice. The texture follows
 * the filter's name and is unregistered with the filter. It does nothing outside the GUI
 * (pvpython, pvbatch: see Examples/bake_texture.py).
 */
#ifndef pqTextureBakingTextures_h
#define pqTextureBakingTextures_h

#include <QMap>
#include <QObject>

class pqDataRepresentation;
class pqPipelineSource;
class pqServerManagerModelItem;
class vtkSMProxy;

class pqTextureBakingTextures : public QObject
{
  Q_OBJECT
public:
  pqTextureBakingTextures(QObject* parent = nullptr);
  ~pqTextureBakingTextures() override;

  void startup();
  void shutdown();

private Q_SLOTS:
  void watch(pqPipelineSource* source);
  void showTextured(pqPipelineSource* source, pqDataRepresentation* representation, int port);
  void rename(pqServerManagerModelItem* item);
  void removeTexture(pqPipelineSource* source);

private:
  /// The source's texture: the one it has, one fed by its second output that is registered
  /// already, or a new one.
  vtkSMProxy* TextureOf(pqPipelineSource* source);

  QMap<pqPipelineSource*, vtkSMProxy*> Textures; // each Texture Baking watched, its texture (registered) or null
};

#endif
