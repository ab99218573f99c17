// SPDX-License-Identifier: BSD-3-Clause
// The filters' quick-launch entries in ParaView's own quick-launch dialog (pqQuickLaunchDialog):
// typing "simplify", "simplification" or "decimate" lists every filter, the labels alone (what
// 5.11 matches without the entries) list none of them for "simplify", and a word of a filter's
// label lists it once, under its label (it was listed twice, issue 45, §5).
#include "MeshSimplificationQuickLaunchAliases.h"

#include "pqQuickLaunchDialog.h"

#include <QAction>
#include <QApplication>
#include <QKeyEvent>
#include <QListWidget>

#include <algorithm>
#include <cstdio>

namespace
{
/// The entries the dialog lists for a query typed into it.
QStringList Search(const QList<QAction*>& actions, const QString& query)
{
  pqQuickLaunchDialog dialog;
  dialog.setActions(actions);
  for (const QChar c : query)
  {
    QKeyEvent key(QEvent::KeyPress, Qt::Key_A + (c.toUpper().unicode() - 'A'), Qt::NoModifier, QString(c));
    QApplication::sendEvent(&dialog, &key);
  }
  QStringList listed;
  const auto* options = dialog.findChild<QListWidget*>("options");
  for (int i = 0; options && i < options->count(); ++i)
  {
    listed << options->item(i)->text();
  }
  return listed;
}
}

int main(int argc, char* argv[])
{
  QApplication application(argc, argv);
  QList<QAction*> aliases, labels;
  for (const MeshSimplificationQuickLaunchAlias& alias : MeshSimplificationQuickLaunchAliases)
  {
    aliases << new QAction(alias.Text, &application);
    aliases.back()->setObjectName(QString("alias") + alias.ProxyName);
    labels << new QAction(QString(alias.ProxyName).replace(QRegExp("([a-z])([A-Z])"), "\\1 \\2"), &application);
    labels.back()->setObjectName(QString("label") + alias.ProxyName);
  }
  int failures = 0;
  for (const char* query : { "simplify", "simplification", "decimate" })
  {
    const QStringList listed = Search(aliases, query);
    std::printf("'%s' -> %s\n", query, qPrintable(listed.join(" | ")));
    failures += listed.size() == aliases.size() ? 0 : 1;
  }
  failures += Search(labels, "simplify").isEmpty() ? 0 : 1;
  for (const QAction* label : labels)
  {
    for (const QString& word : label->text().split(' '))
    {
      const QStringList listed = Search(aliases + labels, word.toLower());
      const bool once = listed.count(label->text()) == 1 &&
        std::none_of(aliases.begin(), aliases.end(), [&listed](const QAction* a) { return listed.contains(a->text()); });
      std::printf("'%s' -> %s\n", qPrintable(word.toLower()), qPrintable(listed.join(" | ")));
      failures += once ? 0 : 1;
    }
  }
  std::printf("%d failed\n", failures);
  return failures == 0 ? 0 : 1;
}
