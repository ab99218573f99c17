// SPDX-License-Identifier: BSD-3-Clause
#include "pqTextureBakingTextures.h"

#include "pqApplicationCore.h"
#include "pqDataRepresentation.h"
#include "pqPipelineSource.h"
#include "pqPVApplicationCore.h"
#include "pqServerManagerModel.h"

#include "vtkNew.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxyIterator.h"
#include "vtkSMPVRepresentationProxy.h"
#include "vtkSMSessionProxyManager.h"
#include "vtkSmartPointer.h"

#include <cstring>
#include <string>

namespace
{
constexpr const char* TexturesGroup = "textures";

bool IsTextureBaking(pqPipelineSource* source)
{
  return source && source->getProxy() && std::strcmp(source->getProxy()->GetXMLName(), "TextureBaking") == 0;
}

/// Whether texture is a Texture proxy fed by the source's second output.
bool FedBy(vtkSMProxy* texture, pqPipelineSource* source)
{
  if (!texture || !texture->GetProperty("Input"))
  {
    return false;
  }
  vtkSMPropertyHelper input(texture, "Input");
  return input.GetNumberOfElements() == 1 && input.GetAsProxy() == source->getProxy() && input.GetOutputPort() == 1;
}

QString TextureName(pqPipelineSource* source)
{
  return source->getSMName() + " Texture";
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
  QObject::connect(model, &pqServerManagerModel::sourceAdded, this, &pqTextureBakingTextures::watch);
  QObject::connect(model, &pqServerManagerModel::preSourceRemoved, this, &pqTextureBakingTextures::removeTexture);
  for (pqPipelineSource* source : model->findItems<pqPipelineSource*>())
  {
    this->watch(source);
  }
}

void pqTextureBakingTextures::shutdown()
{
  for (pqPipelineSource* source : this->Textures.keys())
  {
    this->removeTexture(source);
  }
}

void pqTextureBakingTextures::watch(pqPipelineSource* source)
{
  if (!IsTextureBaking(source) || this->Textures.contains(source))
  {
    return;
  }
  this->Textures[source] = nullptr;
  QObject::connect(source, &pqPipelineSource::representationAdded, this, &pqTextureBakingTextures::showTextured);
  QObject::connect(source, &pqProxy::nameChanged, this, &pqTextureBakingTextures::rename);
}

vtkSMProxy* pqTextureBakingTextures::TextureOf(pqPipelineSource* source)
{
  vtkSMProxy*& texture = this->Textures[source];
  vtkSMSessionProxyManager* proxies = source->proxyManager();
  vtkNew<vtkSMProxyIterator> registered;
  registered->SetSession(proxies->GetSession());
  registered->SetModeToOneGroup();
  for (registered->Begin(TexturesGroup); !texture && !registered->IsAtEnd(); registered->Next())
  {
    texture = FedBy(registered->GetProxy(), source) ? registered->GetProxy() : nullptr;
  }
  if (!texture)
  {
    vtkSmartPointer<vtkSMProxy> made = vtkSmartPointer<vtkSMProxy>::Take(proxies->NewProxy(TexturesGroup, "Texture"));
    if (made)
    {
      vtkSMPropertyHelper(made, "Input").Set(source->getProxy(), 1);
      made->UpdateVTKObjects();
      proxies->RegisterProxy(TexturesGroup, TextureName(source).toUtf8().data(), made);
      texture = made;
    }
  }
  return texture;
}

void pqTextureBakingTextures::showTextured(pqPipelineSource* source, pqDataRepresentation* representation, int port)
{
  vtkSMProxy* proxy = representation ? representation->getProxy() : nullptr;
  if (port != 0 || !proxy || !proxy->GetProperty("Texture"))
  {
    return;
  }
  vtkSMProxy* given = vtkSMPropertyHelper(proxy, "Texture").GetAsProxy();
  if (given) // a state's: kept, and taken as the filter's when it is fed by it
  {
    if (!this->Textures.value(source) && FedBy(given, source))
    {
      this->Textures[source] = given;
    }
    return;
  }
  vtkSMProxy* texture = this->TextureOf(source);
  if (texture)
  {
    vtkSMPropertyHelper(proxy, "Texture").Set(texture);
    vtkSMPVRepresentationProxy::SetScalarColoring(proxy, nullptr, 0);
    proxy->UpdateVTKObjects();
  }
}

void pqTextureBakingTextures::rename(pqServerManagerModelItem* item)
{
  auto* source = qobject_cast<pqPipelineSource*>(item);
  vtkSMProxy* texture = this->Textures.value(source);
  vtkSMSessionProxyManager* proxies = texture ? source->proxyManager() : nullptr;
  const char* old = proxies ? proxies->GetProxyName(TexturesGroup, texture) : nullptr;
  if (old && TextureName(source) != old)
  {
    const std::string previous = old;
    proxies->RegisterProxy(TexturesGroup, TextureName(source).toUtf8().data(), texture);
    proxies->UnRegisterProxy(TexturesGroup, previous.c_str(), texture);
  }
}

void pqTextureBakingTextures::removeTexture(pqPipelineSource* source)
{
  vtkSMProxy* texture = this->Textures.take(source);
  vtkSMSessionProxyManager* proxies = texture ? source->proxyManager() : nullptr;
  const char* name = proxies ? proxies->GetProxyName(TexturesGroup, texture) : nullptr;
  if (name)
  {
    proxies->UnRegisterProxy(TexturesGroup, std::string(name).c_str(), texture);
  }
}
