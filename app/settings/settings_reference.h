// The settings reference (docs/settings.md), generated from the settings table so that it
// cannot drift: `npr-viewer --settings-reference` prints it and CI checks the committed copy.
#pragma once

#include <string>

namespace npr {

std::string settingsReferenceMarkdown();

}  // namespace npr
