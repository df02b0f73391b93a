// SPDX-License-Identifier: GPL-3.0-or-later
// Checks shared by the tests of the scenes a reconstruction's stages make.
#pragma once

#include <gtest/gtest.h>

#include <sculpt/sculpt.hpp>

#include "scene/scene.hpp"

namespace sculpt::testing {

// Every stage of the reconstruction's method builds as a scene.
template <int D>
void expect_every_stage_builds(const Reconstruction<D>& reconstruction) {
  for (scene::Stage stage : scene::stages_of(reconstruction.options.method, D)) {
    scene::Request request;
    request.stage = stage;
    EXPECT_NO_THROW(scene::build_scene(reconstruction, request)) << scene::stage_id(stage);
  }
}

}  // namespace sculpt::testing
