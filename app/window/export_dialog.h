// Ctrl+E: the export dialog (a picture at a chosen size, the lines as SVG, a turntable as a
// video, by the file's extension) and, while an export runs, its progress with a cancel.
// Drawn in the window with Dear ImGui, as the file dialogs are.
#pragma once

#include "app/window/viewer.h"

namespace npr {

// Draws the dialog when Viewer::dialog asks for it, or the running export's progress; call
// between ImGui's new frame and its end.
void drawExportDialog(Viewer& viewer);
// Runs the export for a share of this frame's time; says in the message bar how it ended.
void stepExport(Viewer& viewer);
// Stops the running export; what it was writing is removed.
void cancelExport(Viewer& viewer);

}  // namespace npr
