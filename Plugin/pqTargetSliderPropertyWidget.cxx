// SPDX-License-Identifier: BSD-3-Clause
#include "pqTargetSliderPropertyWidget.h"

#include <pqApplicationCore.h>
#include <pqDoubleRangeWidget.h>
#include <pqIntRangeWidget.h>
#include <pqPipelineSource.h>
#include <pqServerManagerModel.h>
#include <vtkPVDataInformation.h>
#include <vtkPVXMLElement.h>
#include <vtkSMDoubleRangeDomain.h>
#include <vtkSMDoubleVectorProperty.h>
#include <vtkSMPropertyHelper.h>
#include <vtkSMProxy.h>
#include <vtkSMSourceProxy.h>

#include <QHBoxLayout>
#include <QSlider>

#include <algorithm>
#include <limits>

namespace
{
/// Steps of a reduction slider: 0.001 apart, so that a drag visits every level a user can tell
/// apart (ParaView's default, 100, jumps by 1 % of the input).
constexpr int ReductionSteps = 1000;

bool AppliesWhileDragging(vtkSMProxy* proxy)
{
  vtkPVXMLElement* hints = proxy ? proxy->GetHints() : nullptr;
  return hints && hints->FindNestedElementByName("ApplyWhileDragging");
}
}

pqTargetSliderPropertyWidget::pqTargetSliderPropertyWidget(
  vtkSMProxy* smproxy, vtkSMProperty* smproperty, QWidget* parentObject)
  : Superclass(smproxy, parentObject)
{
  // A change is finished where the range widget says so (on release, or at once where typed),
  // or where applyWhileDragged does: not at every change of the value.
  this->setChangeAvailableAsChangeFinished(false);
  auto* layout = new QHBoxLayout(this);
  layout->setMargin(0);
  if (auto* doubles = vtkSMDoubleVectorProperty::SafeDownCast(smproperty))
  {
    auto* range = new pqDoubleRangeWidget(this);
    range->setObjectName("DoubleRangeWidget");
    range->setUseGlobalPrecisionAndNotation(true);
    auto* domain = doubles->FindDomain<vtkSMDoubleRangeDomain>();
    range->setMinimum(domain && domain->GetMinimumExists(0) ? domain->GetMinimum(0) : 0.0);
    range->setMaximum(domain && domain->GetMaximumExists(0) ? domain->GetMaximum(0) : 1.0);
    range->setResolution(ReductionSteps);
    this->addPropertyLink(range, "value", SIGNAL(valueChanged(double)), smproperty);
    this->connect(range, SIGNAL(valueEdited(double)), this, SIGNAL(changeFinished()));
    layout->addWidget(range, 1);
    this->Slider = range->findChild<QSlider*>();
  }
  else
  {
    this->Counts = new pqIntRangeWidget(this);
    this->Counts->setObjectName("IntRangeWidget");
    this->Counts->setMinimum(0);
    this->updateCountMaximum();
    // The input may not have run yet (a filter made from Python before its input updated), and
    // its cells change with it: the maximum follows its updates.
    vtkSMPropertyHelper input(smproxy, "Input", /*quiet=*/true);
    pqServerManagerModel* model = pqApplicationCore::instance()->getServerManagerModel();
    if (auto* source = input.GetAsProxy(0) ? model->findItem<pqPipelineSource*>(input.GetAsProxy(0)) : nullptr)
    {
      this->connect(source, SIGNAL(dataUpdated(pqPipelineSource*)), SLOT(updateCountMaximum()));
    }
    this->addPropertyLink(this->Counts, "value", SIGNAL(valueChanged(int)), smproperty);
    this->connect(this->Counts, SIGNAL(valueEdited(int)), this, SIGNAL(changeFinished()));
    layout->addWidget(this->Counts, 1);
    this->Slider = this->Counts->findChild<QSlider*>();
  }
  // Connected after the range widget's own connection, so the property already holds the value
  // the slider moved to when this asks for it to be applied.
  if (this->Slider && AppliesWhileDragging(smproxy))
  {
    this->connect(this->Slider, SIGNAL(valueChanged(int)), SLOT(applyWhileDragged()));
  }
}

pqTargetSliderPropertyWidget::~pqTargetSliderPropertyWidget() = default;

void pqTargetSliderPropertyWidget::showEvent(QShowEvent* event)
{
  this->updateCountMaximum();
  this->Superclass::showEvent(event);
}

void pqTargetSliderPropertyWidget::applyWhileDragged()
{
  if (this->Slider && this->Slider->isSliderDown())
  {
    Q_EMIT this->changeAvailable();
    Q_EMIT this->changeFinished();
  }
}

void pqTargetSliderPropertyWidget::updateCountMaximum()
{
  if (!this->Counts)
  {
    return;
  }
  long long cells = 0;
  vtkSMPropertyHelper input(this->proxy(), "Input", /*quiet=*/true);
  if (auto* source = vtkSMSourceProxy::SafeDownCast(input.GetAsProxy(0)))
  {
    cells = source->GetDataInformation(input.GetOutputPort(0))->GetNumberOfCells();
  }
  // Never below the value typed, so that showing the slider does not change the target.
  cells = std::max<long long>(cells, this->Counts->value());
  this->Counts->setMaximum(static_cast<int>(std::min<long long>(cells, std::numeric_limits<int>::max())));
}
