#include "pqDeepShadowTechniqueWidget.h"

#include "Core/ShadowTechniques.h"

#include "pqPropertiesPanel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFont>
#include <QVBoxLayout>
#include <QStandardItemModel>

namespace
{
const QString CachedSuffix = "-cached";
}

pqDeepShadowTechniqueWidget::pqDeepShadowTechniqueWidget(vtkSMProxy* proxy, vtkSMProperty* property, QWidget* parent)
  : Superclass(proxy, parent)
{
  this->setShowLabel(true);
  // The box under the menu: the panel is often narrow.
  auto* layout = new QVBoxLayout(this);
  layout->setMargin(pqPropertiesPanel::suggestedMargin());
  layout->setSpacing(pqPropertiesPanel::suggestedVerticalSpacing());
  this->Menu = new QComboBox(this);
  this->Menu->setObjectName("DeepShadowTechniqueMenu");
  this->Cached = new QCheckBox("Cached in a 3D shadow volume", this);
  this->Cached->setObjectName("DeepShadowTechniqueCached");
  this->Cached->setToolTip("Keep the shadows in a 3D shadow volume (NAME-cached): cheaper frames, "
                           "coarser shadows, rebuilt only when the light or the volume changes");
  layout->addWidget(this->Menu);
  layout->addWidget(this->Cached);

  // "No shadows" first, then each group under a heading that cannot be chosen.
  auto* model = new QStandardItemModel(this->Menu);
  auto add = [&](const deepshadow::ShadowTechniqueInfo& technique) {
    auto* item = new QStandardItem(QString::fromStdString(technique.Label + " (" + technique.Name + ")"));
    item->setData(QString::fromStdString(technique.Name), Qt::UserRole);
    item->setToolTip(QString::fromStdString(technique.Summary));
    model->appendRow(item);
  };
  for (const deepshadow::ShadowTechniqueInfo& technique : deepshadow::ShadowTechniques())
  {
    if (technique.Group.empty())
    {
      add(technique);
    }
  }
  for (const std::string& group : deepshadow::ShadowTechniqueGroups())
  {
    auto* heading = new QStandardItem(QString::fromStdString(group));
    QFont font = heading->font();
    font.setBold(true);
    heading->setFont(font);
    heading->setFlags(Qt::NoItemFlags);
    model->appendRow(heading);
    for (const deepshadow::ShadowTechniqueInfo& technique : deepshadow::ShadowTechniques())
    {
      if (technique.Group == group)
      {
        add(technique);
      }
    }
  }
  this->Menu->setModel(model);

  QObject::connect(this->Menu, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this] { this->chosen(); });
  QObject::connect(this->Cached, &QCheckBox::toggled, this, [this] { this->chosen(); });
  this->addPropertyLink(this, "technique", SIGNAL(techniqueChanged()), property);
  this->setChangeAvailableAsChangeFinished(true);
}

pqDeepShadowTechniqueWidget::~pqDeepShadowTechniqueWidget() = default;

QString pqDeepShadowTechniqueWidget::technique() const
{
  const QString name = this->Menu->currentData(Qt::UserRole).toString();
  return name + (this->Cached->isChecked() && this->Cached->isEnabled() ? CachedSuffix : QString());
}

void pqDeepShadowTechniqueWidget::setTechnique(const QString& name)
{
  if (name == this->technique())
  {
    return;
  }
  this->Setting = true;
  const bool cached = name.endsWith(CachedSuffix) && name.size() > CachedSuffix.size();
  const QString base = cached ? name.left(name.size() - CachedSuffix.size()) : name;
  int index = this->Menu->findData(base, Qt::UserRole);
  if (index < 0)
  {
    // A name this build does not know (a state file from another version): kept as it is,
    // the representation says what is wrong with it.
    this->Menu->addItem(name, name);
    index = this->Menu->count() - 1;
  }
  this->Menu->setCurrentIndex(index);
  this->Cached->setChecked(cached);
  this->chosen(); // set from the property: nothing to send back
  this->Setting = false;
}

void pqDeepShadowTechniqueWidget::chosen()
{
  // "none" has no cached variant.
  this->Cached->setEnabled(this->Menu->currentData(Qt::UserRole).toString() != "none");
  if (!this->Setting)
  {
    Q_EMIT this->techniqueChanged();
  }
}
