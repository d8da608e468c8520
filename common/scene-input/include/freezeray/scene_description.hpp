// A scene as a file describes it, before anything is made of it: the camera, the meshes (in world
// space, each triangle naming a material), the materials and lights as parameters, and a block
// of settings per kind. A reader turns one file format into this (scene_readers.hpp); the builder
// (scene_builder.hpp) makes a Scene of it through the registry, so that a new format is one
// reader and touches nothing that builds.
#pragma once

#include "freezeray/camera.hpp"
#include "freezeray/mesh.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace freezeray {

// Parameters as the file gave them, with where they are for messages: a JSON object (a reader of
// another format writes its parameter lists as one), the file and the JSON path within it ("" when
// the file has no such block).
struct ParameterBlock {
    nlohmann::json json = nlohmann::json::object();
    std::string file;
    std::string path;   // "/camera", "/lights/2", "/materials/glass"
    bool given = false; // the file has the block
    // Keys the reader has read itself (the camera's position, ...): the builder does not warn
    // of them as unused, and still offers them as the nearest name of a mistyped key.
    std::vector<std::string> taken;
};

// A material: its name (meshes share materials by name) and its parameters ("type" and the
// type's own), from the mesh file's material library or the scene's own description.
struct MaterialDescription {
    std::string name;
    ParameterBlock parameters;
};

struct SceneDescription {
    std::string file;            // the scene file, for messages
    std::string base_directory;  // relative file names in parameters are relative to it

    // What every camera states, and the camera block's other keys ("type" and the type's own),
    // which the builder gives the camera's factory.
    CameraDescription camera;
    ParameterBlock camera_block;

    // World-space meshes; their face_materials index `materials`.
    std::vector<TriangleMesh> meshes;
    std::vector<MaterialDescription> materials;
    std::vector<ParameterBlock> lights;  // analytic lights and the environment, each with its "type"

    // The blocks of settings, by what reads them: the run's defaults and the integrators' options
    // ("render"), the texture layout and its settings ("textures"), the accelerator ("accelerator").
    ParameterBlock render;
    ParameterBlock textures;
    ParameterBlock accelerator;

    std::vector<std::string> warnings;  // what the reader noticed and passed over
};

}  // namespace freezeray
