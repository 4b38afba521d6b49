/**
 * @class   pqDeepShadowTechniqueWidget
 * @brief   The Properties panel's editor of a Shadowed Volume's ShadowTechnique.
 *
 * A menu of the technique registry's techniques under readable labels, grouped under headings
 * (Exact, Maps, Deep maps, Approximate: deepshadow::ShadowTechniqueInfo::Label and Group), and
 * a "cached" check box for the NAME-cached variants. The property stays the registry's name
 * ("dsm", "dsm-cached"), so Python scripts and state files are unchanged. XML:
 * panel_widget="deepshadow_technique".
 */
#ifndef pqDeepShadowTechniqueWidget_h
#define pqDeepShadowTechniqueWidget_h

#include "pqPropertyWidget.h"

class QCheckBox;
class QComboBox;

class pqDeepShadowTechniqueWidget : public pqPropertyWidget
{
  Q_OBJECT
  Q_PROPERTY(QString technique READ technique WRITE setTechnique NOTIFY techniqueChanged)
  typedef pqPropertyWidget Superclass;

public:
  pqDeepShadowTechniqueWidget(vtkSMProxy* proxy, vtkSMProperty* property, QWidget* parent = nullptr);
  ~pqDeepShadowTechniqueWidget() override;

  /** The registry name chosen: the menu's technique, "-cached" if the box is checked. */
  QString technique() const;
  void setTechnique(const QString& name);

Q_SIGNALS:
  void techniqueChanged();

private:
  void chosen();

  QComboBox* Menu;
  QCheckBox* Cached;
  bool Setting = false;

  Q_DISABLE_COPY(pqDeepShadowTechniqueWidget)
};

#endif
