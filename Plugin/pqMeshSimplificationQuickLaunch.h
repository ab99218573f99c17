// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   pqMeshSimplificationQuickLaunch
 * @brief   finds the Mesh Simplification filters in ParaView's quick launch (Ctrl+Space) when a
 *          user types "simplify", "simplification" or "decimate"
 *
 * ParaView 5.11's quick launch matches the typed words against the menu actions' text only, and
 * a filter's label is also its pvpython name, so the labels stay as they are. This auto-start
 * component of the plugin's GUI side adds one more quick-launch entry per filter whose text
 * carries those words (QuickLaunchAliases) and triggers the filter's own Filters-menu action,
 * enabled as that action is. It does nothing outside the GUI (pvpython, pvbatch).
 */
#ifndef pqMeshSimplificationQuickLaunch_h
#define pqMeshSimplificationQuickLaunch_h

#include <QMap>
#include <QObject>
#include <QPointer>
#include <QString>

class QAction;
class QWidget;

class pqMeshSimplificationQuickLaunch : public QObject
{
  Q_OBJECT
public:
  pqMeshSimplificationQuickLaunch(QObject* parent = nullptr);
  ~pqMeshSimplificationQuickLaunch() override;

  void startup();
  void shutdown();

private Q_SLOTS:
  void matchEnabledStates();
  void triggerFilter();

private:
  QPointer<QWidget> Holder; // never shown: the parent of the alias actions
  QMap<QAction*, QString> Filters; // alias -> the filter's proxy name
};

#endif
