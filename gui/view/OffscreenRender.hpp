#pragma once
/// \file OffscreenRender.hpp
/// Pictures of a model as PNG files without a window on screen (reports, `mcdda render`, tests).
/// Needs an X server (Debian's VTK renders through GLX only); Xvfb is enough.

#include "view/ModelScene.hpp"

#include <functional>
#include <string>

class vtkRenderer;

namespace mcdda::view {

/// The DPI render_png gives its window: 72 up to 800 pixels on the short side, then growing
/// with the picture (capped at 3×) so text and lines keep their share of a large image.
int png_dpi(int width, int height);

/// Renders the scene of build_model_scene off-screen at width×height pixels and writes a PNG
/// to `path`. Writes "<path>.tmp" first and renames it, so a failure never leaves a half-written
/// picture. Throws std::runtime_error with a message naming the cause (no X display, bad size,
/// unwritable path, failed read-back).
void render_png(const Preprocessed& p, const SceneOptions& options, int width, int height,
                const std::string& path);

/// What render_png does around the scene: opens the X display, lets `build` fill the renderer
/// of an off-screen window of width×height pixels (DPI from png_dpi), renders and writes the PNG
/// atomically. Error messages start with `who` ("render_png: ..."). Throws std::runtime_error.
void render_scene_png(const std::function<void(vtkRenderer*)>& build, int width, int height,
                      const std::string& path, const std::string& who = "render_png");

}  // namespace mcdda::view
