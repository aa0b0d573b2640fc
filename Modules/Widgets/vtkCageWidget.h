/**
 * @class   vtkCageWidget
 * @brief   drag, select and transform the corners of a deformation cage in a render window
 *
 * vtkCageWidget is the interactive editor of the boxes of Chen, Ofek, Shum
 * and Levoy, "Interactive Deformation of Light Fields" (I3D 2005), Sec. 5:
 * the animator drags box corners and the light field follows. It is the
 * event half of VTK's widget/representation split (as vtkBoxWidget2 is for
 * vtkBoxRepresentation): it turns mouse and key events into calls of its
 * vtkCageRepresentation, which owns the geometry, the picking, the
 * selection and the edits (and their numeric API).
 *
 * Mouse and keys (with the widget enabled):
 * - **hover** a handle: highlighted (the visible, nearest one; see
 *   vtkCageRepresentation);
 * - **left click** a handle: selects it (replaces the selection);
 *   **shift + left click** toggles it in the selection;
 * - **left drag** a handle: moves the selection (the handle joins it if it
 *   was not selected) in the view plane, or under the X/Y/Z constraint
 *   typed during the drag; one drag is one interaction;
 * - **left click** on empty space clears the selection (a drag there
 *   moves the camera as usual: the widget holds the press back until the
 *   cursor moves more than 3 pixels, then passes it on);
 * - **B**, then left drag: rubber-band selection of the visible handles in
 *   the rectangle (shift held at release adds to the selection);
 * - **A**: selects every point, or clears the selection when all are
 *   selected;
 * - **G / R / S** (with a selection): grab / rotate / scale the selection
 *   about the pivot, following the cursor; during it **X / Y / Z**
 *   constrain to that axis, **shift + X / Y / Z** to the plane
 *   perpendicular to it (typing the same key again removes the
 *   constraint); **left click or Enter** confirms, **Esc or right click**
 *   cancels (the points go back where they started);
 * - **Esc** (otherwise) clears the selection.
 * Keys the widget uses are not passed on to the interactor style (so R, S
 * do not reset the camera or switch to surface rendering while editing);
 * SetKeyboardBindings(false) turns every key off.
 *
 * Events: StartInteractionEvent, InteractionEvent and EndInteractionEvent
 * bracket every drag and modal transform (a cancelled transform still ends
 * with InteractionEvent, back at the start positions, then
 * EndInteractionEvent), and the representation's API edits and
 * vtkCageRepresentation::SelectionChangedEvent are relayed by the widget:
 * an observer of the widget sees every edit as one Start...End bracket, so
 * "one drag = one undoable command" holds when it brackets the scene
 * logic's BeginInteraction() / EndInteraction() with them.
 *
 * @sa vtkCageRepresentation vtkDeformationCage
 */
#ifndef vtkCageWidget_h
#define vtkCageWidget_h

#include "lfdWidgetsModule.h" // For export macro
#include "vtkAbstractWidget.h"

class vtkCageRepresentation;
class vtkCallbackCommand;

class LFDWIDGETS_EXPORT vtkCageWidget : public vtkAbstractWidget
{
public:
  static vtkCageWidget* New();
  vtkTypeMacro(vtkCageWidget, vtkAbstractWidget);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The representation (created by CreateDefaultRepresentation() when
   * none is set).
   */
  void SetRepresentation(vtkCageRepresentation* rep);
  vtkCageRepresentation* GetCageRepresentation();
  void CreateDefaultRepresentation() override;
  ///@}

  ///@{
  /**
   * Whether the widget reacts to keys (B, A, G, R, S, X, Y, Z, Enter,
   * Esc). Default on.
   */
  vtkSetMacro(KeyboardBindings, bool);
  vtkGetMacro(KeyboardBindings, bool);
  vtkBooleanMacro(KeyboardBindings, bool);
  ///@}

protected:
  vtkCageWidget();
  ~vtkCageWidget() override;

  bool KeyboardBindings = true;

private:
  vtkCageWidget(const vtkCageWidget&) = delete;
  void operator=(const vtkCageWidget&) = delete;

  // Callbacks of the callback mapper.
  static void SelectAction(vtkAbstractWidget* widget);
  static void EndSelectAction(vtkAbstractWidget* widget);
  static void MoveAction(vtkAbstractWidget* widget);
  static void CancelAction(vtkAbstractWidget* widget);
  static void KeyPressAction(vtkAbstractWidget* widget);

  // Relays the representation's events to the widget's observers.
  static void RelayEvent(vtkObject* caller, unsigned long event, void* clientData, void* callData);

  bool HandleModalKey(const char* key, bool shift);
  void BeginInteraction();
  void FinishInteraction(bool cancel);

  vtkCallbackCommand* RelayCommand;
  vtkCageRepresentation* ObservedRepresentation = nullptr;
  int WidgetState = 0;
  bool RubberBandArmed = false;
  bool PassingPress = false;
  double PressPosition[2] = { 0.0, 0.0 };
};

#endif
