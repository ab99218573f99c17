// SPDX-License-Identifier: BSD-3-Clause
#include "pqTextureBakingTextures.h"

#include "pqApplicationCore.h"
#include "pqDataRepresentation.h"
#include "pqPipelineSource.h"
#include "pqPVApplicationCore.h"
#include "pqServerManagerModel.h"

#include "vtkSMPropertyHelper.h"
#include "vtkSMPVRepresentationProxy.h"
#include "vtkSMSessionProxyManager.h"
#include "vtkSMSourceProxy.h"
#include "vtkSmartPointer.h"

#include <cstring>

namespace
{
constexpr const char* TexturesGroup = "textures";

bool IsTextureBaking(pqPipelineSource* source)
{
  return source && source->getProxy() && std::strcmp(source->getProxy()->GetXMLName(), "TextureBaking") == 0;
}
}

pqTextureBakingTextures::pqTextureBakingTextures(QObject* parent)
  : QObject(parent)
{
}

pqTextureBakingTextures::~pqTextureBakingTextures() = default;

void pqTextureBakingTextures::startup()
{
  if (!pqPVApplicationCore::instance())
  {
    return; // not the ParaView GUI
  }
  pqServerManagerModel* model = pqApplicationCore::instance()->getServerManagerModel();
  QObject::connect(model, &pqServerManagerModel::sourceAdded, this, &pqTextureBakingTextures::addTexture);
  QObject::connect(model, &pqServerManagerModel::preSourceRemoved, this, &pqTextureBakingTextures::removeTexture);
  for (pqPipelineSource* source : model->findItems<pqPipelineSource*>())
  {
    this->addTexture(source);
  }
}

void pqTextureBakingTextures::shutdown()
{
  for (pqPipelineSource* source : this->Textures.keys())
  {
    this->removeTexture(source);
  }
}

void pqTextureBakingTextures::addTexture(pqPipelineSource* source)
{
  if (!IsTextureBaking(source) || this->Textures.contains(source))
  {
    return;
  }
  vtkSMSessionProxyManager* proxies = source->proxyManager();
  vtkSmartPointer<vtkSMProxy> texture = vtkSmartPointer<vtkSMProxy>::Take(proxies->NewProxy(TexturesGroup, "Texture"));
  if (!texture)
  {
    return;
  }
  vtkSMPropertyHelper(texture, "Input").Set(source->getProxy(), 1);
  texture->UpdateVTKObjects();
  proxies->RegisterProxy(TexturesGroup, (source->getSMName() + " Texture").toUtf8().data(), texture);
  this->Textures[source] = texture;
  QObject::connect(source, &pqPipelineSource::representationAdded, this, &pqTextureBakingTextures::showTextured);
}

void pqTextureBakingTextures::removeTexture(pqPipelineSource* source)
{
  vtkSMProxy* texture = this->Textures.take(source);
  if (!texture)
  {
    return;
  }
  vtkSMSessionProxyManager* proxies = source->proxyManager();
  const char* name = proxies->GetProxyName(TexturesGroup, texture);
  if (name)
  {
    proxies->UnRegisterProxy(TexturesGroup, name, texture);
  }
}

void pqTextureBakingTextures::showTextured(pqPipelineSource* source, pqDataRepresentation* representation, int port)
{
  vtkSMProxy* proxy = representation ? representation->getProxy() : nullptr;
  if (port != 0 || !proxy || !proxy->GetProperty("Texture") || !this->Textures.contains(source))
  {
    return;
  }
  vtkSMPropertyHelper(proxy, "Texture").Set(this->Textures[source]);
  vtkSMPVRepresentationProxy::SetScalarColoring(proxy, nullptr, 0);
  proxy->UpdateVTKObjects();
}
