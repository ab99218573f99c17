// SPDX-License-Identifier: BSD-3-Clause
#include "pqMeshSimplificationQuickLaunch.h"

#include "MeshSimplificationQuickLaunchAliases.h"

#include "pqPVApplicationCore.h"

#include <QAction>
#include <QApplication>
#include <QStringList>
#include <QWidget>

namespace
{
/// The Filters-menu action of a proxy: pqProxyGroupMenuManager names it after the proxy and
/// keeps {group, name} in its data.
QAction* FilterAction(const QString& proxyName)
{
  for (QWidget* window : QApplication::topLevelWidgets())
  {
    for (QAction* action : window->findChildren<QAction*>(proxyName))
    {
      if (action->data().toStringList() == QStringList({ "filters", proxyName }))
      {
        return action;
      }
    }
  }
  return nullptr;
}
}

pqMeshSimplificationQuickLaunch::pqMeshSimplificationQuickLaunch(QObject* parent)
  : QObject(parent)
{
}

pqMeshSimplificationQuickLaunch::~pqMeshSimplificationQuickLaunch()
{
  delete this->Holder;
}

void pqMeshSimplificationQuickLaunch::startup()
{
  pqPVApplicationCore* core = pqPVApplicationCore::instance();
  if (!core)
  {
    return; // not the ParaView GUI
  }
  this->Holder = new QWidget();
  for (const MeshSimplificationQuickLaunchAlias& alias : MeshSimplificationQuickLaunchAliases)
  {
    QAction* action = new QAction(QString::fromUtf8(alias.Text), this->Holder);
    // The quick launch keys its entries by object name: one of our own per alias.
    action->setObjectName(QString("MeshSimplificationQuickLaunch%1").arg(alias.ProxyName));
    this->Filters[action] = alias.ProxyName;
    QObject::connect(action, &QAction::triggered, this, &pqMeshSimplificationQuickLaunch::triggerFilter);
  }
  core->registerForQuicklaunch(this->Holder);
  QObject::connect(core, &pqPVApplicationCore::aboutToShowQuickLaunch, this,
    &pqMeshSimplificationQuickLaunch::matchEnabledStates);
}

void pqMeshSimplificationQuickLaunch::shutdown() {}

void pqMeshSimplificationQuickLaunch::matchEnabledStates()
{
  for (auto entry = this->Filters.begin(); entry != this->Filters.end(); ++entry)
  {
    QAction* filter = FilterAction(entry.value());
    entry.key()->setEnabled(filter && filter->isEnabled());
  }
}

void pqMeshSimplificationQuickLaunch::triggerFilter()
{
  auto* alias = qobject_cast<QAction*>(this->sender());
  if (QAction* filter = alias ? FilterAction(this->Filters.value(alias)) : nullptr)
  {
    filter->trigger();
  }
}
