// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   pqTextureBakingTextures
 * @brief   shows Texture Baking's surface textured in the ParaView GUI: each Texture Baking gets
 *          a texture fed by its second output, named after it
 *
 * ParaView 5.11's Texture menu (Properties, Lighting) lists the proxies of the "textures" group
 * and image files; a filter's image output is neither. This auto-start component of the
 * plugin's GUI side registers, for each Texture Baking, a Texture proxy fed by its second output
 * ("<name> Texture"), so it is in that menu for any representation, and sets it on the
 * representations of the filter's first output as they are made, coloured by Solid Color (scalar
 * colours would tint the texture). It unregisters the texture with its filter. It does nothing
 * outside the GUI (pvpython, pvbatch: see Examples/bake_texture.py).
 */
#ifndef pqTextureBakingTextures_h
#define pqTextureBakingTextures_h

#include <QMap>
#include <QObject>
#include <QPointer>

class pqPipelineSource;
class pqDataRepresentation;
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
  void addTexture(pqPipelineSource* source);
  void removeTexture(pqPipelineSource* source);
  void showTextured(pqPipelineSource* source, pqDataRepresentation* representation, int port);

private:
  QMap<pqPipelineSource*, vtkSMProxy*> Textures; // each Texture Baking's texture (registered)
};

#endif
