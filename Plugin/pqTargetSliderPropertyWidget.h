// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   pqTargetSliderPropertyWidget
 * @brief   the slider of a Mesh Simplification target (Target Reduction, Target Triangle Count)
 *          that applies while it is dragged, for the filters that change level at once
 *
 * ParaView's own slider applies a value only when the mouse is released, even with Auto Apply
 * on: right for a filter that takes seconds, wrong for Progressive Mesh, which re-extracts a
 * level from its cached sequence in milliseconds. This widget (panel_widget
 * "mesh_simplification_target_slider" on the base proxy's targets) is that slider, plus:
 * - on a proxy whose hints hold `<ApplyWhileDragging/>`, every move of the dragged slider is a
 *   finished change, so Auto Apply applies it and the view plays through the levels. Qt merges
 *   the mouse moves that arrive while a level is shown, so the drag never falls behind the
 *   mouse. Without Auto Apply a move only enables Apply, as any edit does;
 * - a triangle count gets a slider from 0 to the input's number of cells (ParaView's default
 *   for a count with no upper bound is a bare text field), refreshed whenever the input's data
 *   is updated and whenever the slider is shown.
 * On other proxies it behaves as ParaView's slider: the value is applied on release.
 */
#ifndef pqTargetSliderPropertyWidget_h
#define pqTargetSliderPropertyWidget_h

#include <pqPropertyWidget.h>

#include <QPointer>

class QSlider;
class pqIntRangeWidget;

class pqTargetSliderPropertyWidget : public pqPropertyWidget
{
  Q_OBJECT
  typedef pqPropertyWidget Superclass;

public:
  pqTargetSliderPropertyWidget(vtkSMProxy* proxy, vtkSMProperty* property, QWidget* parent = nullptr);
  ~pqTargetSliderPropertyWidget() override;

protected:
  void showEvent(QShowEvent* event) override;

private Q_SLOTS:
  /// While the slider is held down: the value it moved to is a finished change.
  void applyWhileDragged();
  /// A count's slider ends at the input's number of cells (never below the value set).
  void updateCountMaximum();

private:
  QPointer<QSlider> Slider;           // the slider inside the range widget
  QPointer<pqIntRangeWidget> Counts; // only for a triangle count
};

#endif
