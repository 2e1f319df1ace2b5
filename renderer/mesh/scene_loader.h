// Loading a file as a scene (scene_description.h): glTF as its nodes' objects, cameras and
// lights; every other format (and a generated mesh's name) as one object placed where the file
// put it. The same input gate and readers as loadMesh (mesh_loader.h).
#pragma once

#include <string>

#include "renderer/core/result.h"
#include "renderer/mesh/scene_description.h"

namespace npr {

struct SceneLoadOptions {
  bool splitObjects = false;  // OBJ: each `o` and `g` group an object of its own (--split-objects)
  bool allWarnings = false;   // every warning, not the first three of each kind (--verbose)
};
[[nodiscard]] Result<LoadedScene> loadScene(const std::string& nameOrPath, const SceneLoadOptions& options = {});

// The scene's load report as one line of JSON (--info): the file's report with its objects,
// cameras, lights, animations and skins.
std::string sceneReportJson(const LoadedScene& scene);

// The transform that puts a loader's centred and scaled mesh back where its file had it.
glm::mat4 filePlacement(const LoadReport& report);

}  // namespace npr
