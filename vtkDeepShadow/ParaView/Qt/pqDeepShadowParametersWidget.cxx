#include "pqDeepShadowParametersWidget.h"

#include "Core/ShadowParameterText.h"
#include "Core/ShadowTechniques.h"

#include "pqCoreUtilities.h"
#include "pqPropertiesPanel.h"
#include "vtkCommand.h"
#include "vtkSMProperty.h"
#include "vtkSMProxy.h"
#include "vtkSMUncheckedPropertyHelper.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QVBoxLayout>

#include <map>
#include <vector>
#include <stdexcept>

namespace
{
// Marks a field whose text the parameter does not accept (cleared when it does).
void MarkInvalid(QLineEdit* field, const QString& problem)
{
  field->setStyleSheet(problem.isEmpty() ? QString() : "QLineEdit { background-color: #ffd0d0; }");
  field->setToolTip(problem.isEmpty() ? field->property("help").toString() : problem);
}
}

pqDeepShadowParametersWidget::pqDeepShadowParametersWidget(vtkSMProxy* proxy, vtkSMProperty* property, QWidget* parent)
  : Superclass(proxy, parent)
  , TechniqueProperty(proxy->GetProperty("ShadowTechnique"))
{
  this->setShowLabel(false);
  auto* layout = new QVBoxLayout(this);
  layout->setMargin(pqPropertiesPanel::suggestedMargin());
  layout->setSpacing(pqPropertiesPanel::suggestedVerticalSpacing());
  this->Fields = new QWidget(this);
  this->Form = new QFormLayout(this->Fields);
  this->Form->setMargin(0);
  this->Form->setHorizontalSpacing(pqPropertiesPanel::suggestedHorizontalSpacing());
  this->Form->setVerticalSpacing(pqPropertiesPanel::suggestedVerticalSpacing());
  layout->addWidget(this->Fields);
  auto* textRow = new QFormLayout();
  textRow->setMargin(0);
  this->TextField = new QLineEdit(this);
  this->TextField->setObjectName("DeepShadowParameterText");
  this->TextField->setPlaceholderText("KEY=VALUE ... (the technique's defaults)");
  this->TextField->setToolTip("The parameters as KEY=VALUE pairs, as the fields above write them "
                              "(the deepshadow tool's option names)");
  textRow->addRow("Shadow Parameters", this->TextField);
  layout->addLayout(textRow);
  QObject::connect(this->TextField, &QLineEdit::editingFinished, this, [this] {
    if (this->TextField->text() != this->Text)
    {
      this->Text = this->TextField->text();
      this->showText();
      Q_EMIT this->textChanged();
    }
  });

  this->addPropertyLink(this, "text", SIGNAL(textChanged()), property);
  this->setChangeAvailableAsChangeFinished(true);
  if (this->TechniqueProperty)
  {
    // The technique menu sets the property (unchecked first, then applied).
    pqCoreUtilities::connect(this->TechniqueProperty, vtkCommand::UncheckedPropertyModifiedEvent, this, SLOT(rebuild()));
    pqCoreUtilities::connect(this->TechniqueProperty, vtkCommand::ModifiedEvent, this, SLOT(rebuild()));
  }
  this->rebuild();
}

pqDeepShadowParametersWidget::~pqDeepShadowParametersWidget() = default;

QString pqDeepShadowParametersWidget::text() const
{
  return this->Text;
}

void pqDeepShadowParametersWidget::setText(const QString& text)
{
  if (text == this->Text)
  {
    return;
  }
  this->Text = text;
  this->TextField->setText(text);
  this->showText();
}

void pqDeepShadowParametersWidget::rebuild()
{
  const char* chosen = this->TechniqueProperty ? vtkSMUncheckedPropertyHelper(this->TechniqueProperty).GetAsString() : nullptr;
  const std::string name = chosen ? chosen : "";
  if (name == this->Technique && this->Form->rowCount() > 0)
  {
    return;
  }
  const bool changed = !this->Technique.empty() || this->Form->rowCount() > 0;
  this->Technique = name;
  while (this->Form->rowCount() > 0)
  {
    this->Form->removeRow(0);
  }
  bool cached = false;
  const deepshadow::ShadowTechniqueInfo* technique = deepshadow::FindShadowTechnique(name, &cached);
  if (changed && technique)
  {
    this->DropUnread(*technique);
  }
  if (!technique || technique->Kind == deepshadow::ShadowKind::None)
  {
    this->Form->addRow(new QLabel(technique ? "No parameters: no shadows." : "Unknown technique.", this->Fields));
    return;
  }
  const deepshadow::ShadowParameters defaults = technique->DefaultParameters(cached);
  // The technique's own parameters first, then those every technique reads; the cache's
  // size only where there is a cache.
  std::vector<const deepshadow::ShadowParameterInfo*> shown;
  for (const std::string& key : technique->Keys)
  {
    shown.push_back(deepshadow::FindShadowParameter(key));
  }
  for (const std::string& key : deepshadow::SharedShadowParameterKeys())
  {
    if (key != "shadow-volume-size" || cached)
    {
      shown.push_back(deepshadow::FindShadowParameter(key));
    }
  }
  for (const deepshadow::ShadowParameterInfo* parameter : shown)
  {
    if (!parameter)
    {
      continue;
    }
    const deepshadow::ShadowParameterInfo& info = *parameter;
    const std::string key = info.Key;
    const QString fallback = QString::fromStdString(info.Format(info.Get(defaults)));
    const QString help =
      QString::fromStdString(info.Help + " (" + info.RangeText() + "); default ") + fallback;
    std::vector<std::string> values = info.Choices;
    for (double allowed : info.Allowed)
    {
      values.push_back(info.Format({ allowed }));
    }
    QWidget* field = nullptr;
    if (!values.empty())
    {
      auto* menu = new QComboBox(this->Fields);
      menu->addItem("default: " + fallback, QString());
      for (const std::string& value : values)
      {
        menu->addItem(QString::fromStdString(value), QString::fromStdString(value));
      }
      QObject::connect(menu, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
        [this, menu, key] { this->edited(key, menu->currentData().toString().toStdString()); });
      field = menu;
    }
    else
    {
      auto* line = new QLineEdit(this->Fields);
      line->setPlaceholderText("default: " + fallback);
      line->setProperty("help", help);
      QObject::connect(line, &QLineEdit::editingFinished, this, [this, line, key] {
        const std::string value = line->text().trimmed().toStdString();
        try
        {
          if (!value.empty())
          {
            deepshadow::FindShadowParameter(key)->Parse(value);
          }
        }
        catch (const std::invalid_argument& problem)
        {
          MarkInvalid(line, QString::fromStdString(problem.what()));
          return;
        }
        MarkInvalid(line, QString());
        this->edited(key, value);
      });
      field = line;
    }
    field->setObjectName(QString::fromStdString(key));
    field->setToolTip(help);
    this->Form->addRow(QString::fromStdString(key), field);
  }
  this->TextField->setText(this->Text);
  this->showText();
}

void pqDeepShadowParametersWidget::DropUnread(const deepshadow::ShadowTechniqueInfo& technique)
{
  // Another technique chosen: the pairs it does not read go (they would be an error).
  std::string text = this->Text.toStdString();
  try
  {
    for (const auto& pair : deepshadow::SplitShadowParameterText(text))
    {
      if (!technique.Reads(pair.first))
      {
        text = deepshadow::SetShadowParameterInText(text, pair.first, "");
      }
    }
  }
  catch (const std::invalid_argument&)
  {
    return; // typed by hand and not parsed: left for the representation to report
  }
  if (text != this->Text.toStdString())
  {
    this->Text = QString::fromStdString(text);
    this->TextField->setText(this->Text);
    Q_EMIT this->textChanged();
  }
}

void pqDeepShadowParametersWidget::edited(const std::string& key, const std::string& value)
{
  if (this->Setting)
  {
    return;
  }
  try
  {
    this->Text = QString::fromStdString(deepshadow::SetShadowParameterInText(this->Text.toStdString(), key, value));
  }
  catch (const std::invalid_argument&)
  {
    // The text does not parse (typed by hand): the field's pair goes after it as it is.
    this->Text += QString::fromStdString(" " + key + "=" + value);
  }
  this->TextField->setText(this->Text);
  Q_EMIT this->textChanged();
}

void pqDeepShadowParametersWidget::showText()
{
  std::map<std::string, std::string> given;
  try
  {
    for (const auto& pair : deepshadow::SplitShadowParameterText(this->Text.toStdString()))
    {
      given[pair.first] = pair.second;
    }
  }
  catch (const std::invalid_argument&)
  {
    // Shown as the technique's defaults; the representation says what is wrong.
  }
  this->Setting = true;
  for (int row = 0; row < this->Form->rowCount(); ++row)
  {
    QLayoutItem* item = this->Form->itemAt(row, QFormLayout::FieldRole);
    QWidget* field = item ? item->widget() : nullptr;
    if (!field)
    {
      continue;
    }
    const auto found = given.find(field->objectName().toStdString());
    const QString value = found != given.end() ? QString::fromStdString(found->second) : QString();
    if (auto* menu = qobject_cast<QComboBox*>(field))
    {
      const int index = menu->findData(value);
      menu->setCurrentIndex(index >= 0 ? index : 0);
    }
    else if (auto* line = qobject_cast<QLineEdit*>(field))
    {
      line->setText(value);
      MarkInvalid(line, QString());
    }
  }
  this->Setting = false;
}
