/**
 * @class   pqDeepShadowParametersWidget
 * @brief   The Properties panel's editor of a Shadowed Volume's ShadowParameters.
 *
 * One field per parameter the chosen technique reads (deepshadow::ShadowTechniqueInfo::
 * Reads, with the registry's ranges and help as tool tips): a menu where the values are a
 * few (pcf, cssm-offsets, ...), a text field otherwise, each showing the technique's own
 * default until a value is given. Beneath, the KEY=VALUE text the fields write, which stays
 * editable and is what the property holds, so scripts and state files are unchanged. The
 * form follows the ShadowTechnique property. XML: panel_widget="deepshadow_parameters".
 */
#ifndef pqDeepShadowParametersWidget_h
#define pqDeepShadowParametersWidget_h

#include "pqPropertyWidget.h"

#include <string>

namespace deepshadow
{
struct ShadowTechniqueInfo;
}
class QFormLayout;
class QLineEdit;
class QWidget;

class pqDeepShadowParametersWidget : public pqPropertyWidget
{
  Q_OBJECT
  Q_PROPERTY(QString text READ text WRITE setText NOTIFY textChanged)
  typedef pqPropertyWidget Superclass;

public:
  pqDeepShadowParametersWidget(vtkSMProxy* proxy, vtkSMProperty* property, QWidget* parent = nullptr);
  ~pqDeepShadowParametersWidget() override;

  /** The KEY=VALUE text. */
  QString text() const;
  void setText(const QString& text);

Q_SIGNALS:
  void textChanged();

private Q_SLOTS:
  /** The technique changed: one field per parameter it reads (and the text only those). */
  void rebuild();

private:
  /** A field's value (empty: the technique's default) into the text. */
  void edited(const std::string& key, const std::string& value);
  /** The fields from the text. */
  void showText();
  /** Removes from the text the keys `technique` does not read. */
  void DropUnread(const deepshadow::ShadowTechniqueInfo& technique);

  vtkSMProperty* TechniqueProperty;
  std::string Technique;
  QString Text;
  QWidget* Fields;
  QFormLayout* Form;
  QLineEdit* TextField;
  bool Setting = false;

  Q_DISABLE_COPY(pqDeepShadowParametersWidget)
};

#endif
