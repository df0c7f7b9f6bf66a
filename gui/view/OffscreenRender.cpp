#include "view/OffscreenRender.hpp"

#include "view/DisplayCheck.hpp"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace mcdda::view {

namespace {

void remove_quietly(const std::filesystem::path& path)
{
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
}

}  // namespace

int png_dpi(int width, int height)
{
    const double scale = std::clamp(std::min(width, height) / 800.0, 1.0, 3.0);
    return static_cast<int>(std::lround(72.0 * scale));
}

void render_png(const Preprocessed& p, const SceneOptions& options, int width, int height,
                const std::string& path)
{
    render_scene_png([&](vtkRenderer* renderer) { build_model_scene(renderer, p, options); }, width, height, path);
}

void render_scene_png(const std::function<void(vtkRenderer*)>& build, int width, int height,
                      const std::string& path, const std::string& who)
{
    constexpr int largest = 16384;
    if (width <= 0 || height <= 0 || width > largest || height > largest)
        throw std::runtime_error(who + ": the image size must be between 1 and " + std::to_string(largest) +
                                 " pixels (got " + std::to_string(width) + "x" + std::to_string(height) + ")");
    if (path.empty()) throw std::runtime_error(who + ": no output file given");
    std::string problem;
    const XConnection connection = open_x_display(problem);  // outlives the window below
    if (!connection) throw std::runtime_error(who + ": " + problem);

    const std::filesystem::path target(path);
    const std::filesystem::path temporary(path + ".tmp");
    const std::filesystem::path folder = target.parent_path();
    if (!folder.empty() && !std::filesystem::is_directory(folder))
        throw std::runtime_error(who + ": cannot write " + path + ": folder " + folder.string() +
                                 " does not exist");
    // Whether the file can be written is known before rendering, with the system's reason
    // (VTK's PNG writer reports any failure to open as "Ran out of disk space").
    if (std::FILE* probe = std::fopen(temporary.string().c_str(), "wb")) {
        std::fclose(probe);
    } else {
        const std::string reason = std::strerror(errno);
        throw std::runtime_error(who + ": cannot write " + path + ": " + reason);
    }
    struct RemoveTemporary {  // whatever fails below, no stray .tmp file stays behind
        const std::filesystem::path& file;
        ~RemoveTemporary() { remove_quietly(file); }
    } cleanup{temporary};

    vtkNew<vtkRenderWindow> window;
    window->SetDisplayId(connection.get());
    window->SetOffScreenRendering(1);
    window->SetSize(width, height);
    window->SetDPI(png_dpi(width, height));
    window->SetMultiSamples(4);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    build(renderer);
    window->Render();

    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    grab->SetInputBufferTypeToRGB();
    grab->ReadFrontBufferOff();
    grab->ShouldRerenderOff();
    grab->Update();
    int dims[3] = {0, 0, 0};
    grab->GetOutput()->GetDimensions(dims);
    if (dims[0] != width || dims[1] != height)
        throw std::runtime_error(who + ": reading back the rendered image failed (got " +
                                 std::to_string(dims[0]) + "x" + std::to_string(dims[1]) + " pixels)");

    vtkNew<vtkPNGWriter> writer;
    writer->SetFileName(temporary.string().c_str());
    writer->SetInputConnection(grab->GetOutputPort());
    errno = 0;
    // Failures are reported below in words; VTK's own log lines would only repeat them.
    const int warnings = vtkObject::GetGlobalWarningDisplay();
    vtkObject::SetGlobalWarningDisplay(0);
    writer->Write();
    vtkObject::SetGlobalWarningDisplay(warnings);
    if (writer->GetErrorCode() != 0 || !std::filesystem::exists(temporary)) {
        const std::string reason = errno != 0 ? std::strerror(errno) : "the PNG writer failed";
        remove_quietly(temporary);
        throw std::runtime_error(who + ": cannot write " + temporary.string() + ": " + reason);
    }
    window->Finalize();

    std::error_code error;
    std::filesystem::rename(temporary, target, error);
    if (error) {
        remove_quietly(temporary);
        throw std::runtime_error(who + ": cannot rename " + temporary.string() + " to " + path + ": " +
                                 error.message());
    }
}

}  // namespace mcdda::view
