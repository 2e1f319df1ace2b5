// The settings reference (the README's section of that name), generated from the settings
// table so that it cannot drift: `npr-viewer --settings-reference` prints it, between two
// marker comments, and CI checks the README's copy.
#pragma once

#include <string>

namespace npr {

std::string settingsReferenceMarkdown();

}  // namespace npr
