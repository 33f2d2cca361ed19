// Screen-space volumetric obscurance (Loos & Sloan 2010) over a rendered scene's depth and
// view-space normals, applied to its colour: estimate (obscurance_glsl.h) at full or half
// resolution, an edge-aware blur, then the colour multiplied by the result (or the result shown
// alone). Style-independent: the engine runs it after any plugin's scene passes, before the
// HUD. The sample sets are the committed electrostatic tables (sample_tables.h); area1 first
// builds a mip chain of depth moments; the reference mode is neither randomised nor blurred.
// The estimate and the blur run as compute programs or over full-screen triangles, or the way
// a short trial measures faster on this GPU (vo_compute; stage_trial.h, stage_clock.h).
#pragma once

#include <array>
#include <string>

#include "gl/handles.h"
#include "gl/program.h"
#include "obscurance/obscurance_settings.h"
#include "obscurance/stage_clock.h"
#include "obscurance/stage_trial.h"

namespace nq::npr::obscurance {

// The scene the pass reads and writes: a framebuffer whose colour attachment 0 is the image,
// its depth texture (a symmetric perspective's depths) and its normal texture (view-space,
// n * 0.5 + 0.5, alpha 1 where a surface should receive obscurance).
struct SceneTextures {
    GLuint framebuffer = 0;
    GLuint colour_texture = 0;  // attachment 0's; read only when compositing elsewhere
    GLuint depth_texture = 0;
    GLuint normal_texture = 0;
    int width = 0, height = 0;
    float projection[16] = {};  // column-major, view to clip
};

// Where the composite may write instead of multiplying the scene's colour in place: another
// framebuffer's rectangle (x, y, width, height) of the scene's size, e.g. the window, so that
// no copy of the scene need follow. Its draw buffers are used as they are set.
struct CompositeTarget {
    GLuint framebuffer = 0;
    int viewport[4] = {};
};

// Optional GPU-time markers around each stage ("vo_moments", "vo_estimate", "vo_blur",
// "vo_composite"), e.g. the engine's timer queries; either function may be null.
struct PassMarkers {
    void (*begin)(void* context, const char* stage) = nullptr;
    void (*end)(void* context) = nullptr;
    void* context = nullptr;
};

class ObscurancePass {
  public:
    explicit ObscurancePass(gl::ObjectTracker* tracker = nullptr)
        : tracker_(tracker), clock_(tracker) {}

    void set_markers(const PassMarkers& markers) { markers_ = markers; }

    // Multiplies the scene's colour by its obscurance: in place, or into `elsewhere` (the
    // scene's colour times its obscurance, the scene left as it was). Leaves blending, depth
    // testing and the viewport as they were found, and the scene framebuffer bound with both of
    // its colour outputs (or `elsewhere`'s). False with `error` when a program does not build
    // (nothing drawn).
    bool apply(const SceneTextures& scene, const ObscuranceSettings& settings, std::string& error,
               const CompositeTarget* elsewhere = nullptr);

    // How the last apply ran the estimate and the blur (vo_compute; always fragment without
    // GL 4.3).
    StagePath ran() const { return path_; }
    // vo_compute 2: the trial of the two paths (the present one, or the last decided), and how
    // many trials have been decided (a new trial starts when the mode, the sample count, the
    // resolution or the blur changes).
    const StageTrial& trial() const { return trial_; }
    int decisions() const { return decisions_; }

    // The last result (RGBA16F: open in red, 1 = open; then the texel's distance and normal
    // x, y for the blur), at the pass's resolution; 0 before the first apply.
    GLuint open_texture() const { return result_ ? result_->id() : 0; }
    // area1's depth moments (RG32F, mipmapped: mean distance, mean squared distance); 0 until
    // area1 has run.
    GLuint moments_texture() const { return moments_.texture ? moments_.texture.id() : 0; }

    void reset();

  private:
    struct Target {
        gl::Texture texture;
        gl::Framebuffer framebuffer;
    };
    // Which table an estimate program holds.
    struct SampleTableKey {
        SampleMethod method = SampleMethod::electrostatic;
        int count = 0;
        bool operator==(const SampleTableKey&) const = default;
    };
    bool build(gl::Program& program, const gl::ProgramSource& source, std::string& error);
    bool build_fullscreen(gl::Program& program, const char* name, const std::string& fragment,
                          std::string& error);
    // The estimate programs (one per mode) and the blur, built to run one way.
    struct StagePrograms {
        std::array<gl::Program, kObscuranceModes> estimate;
        std::array<SampleTableKey, kObscuranceModes> uploaded{};  // per estimate program
        gl::Program blur;
    };
    // What a trial of the two paths measured; another key, another trial.
    struct TrialKey {
        ObscuranceMode mode = ObscuranceMode::lines5;
        int samples = 0, width = 0, height = 0;
        bool blur = false;
        bool operator==(const TrialKey&) const = default;
    };
    bool build_stage(gl::Program& program, const char* name, const std::string& body,
                     StagePath path, std::string& error);
    bool build_estimate(ObscuranceMode mode, int samples, StagePath path, std::string& error);
    bool build_blur(StagePath path, std::string& error);
    bool build_shared(ObscuranceMode mode, std::string& error);
    bool build_programs(ObscuranceMode mode, int samples, std::string& error);
    int choose_path(const TrialKey& key);
    void read_trial();
    void stamp(int trial_frame, int stamp);
    void upload_samples(StagePrograms& programs, ObscuranceMode mode, SampleTableKey table);
    bool make_target(Target& target, GLenum format, int levels, int width, int height,
                     std::string& error);
    bool prepare_targets(int width, int height, std::string& error);
    bool prepare_moments(int width, int height, std::string& error);
    void build_moments(const SceneTextures& scene);
    void estimate(const SceneTextures& scene, const ObscuranceSettings& settings, int samples);
    void run_stage(const Target& to, StagePath path);
    void blur();
    void composite(const SceneTextures& scene, const ObscuranceSettings& settings,
                   const CompositeTarget* elsewhere);
    void bind_scene(gl::Program& program, const SceneTextures& scene);
    void mark_begin(const char* stage) const {
        if (markers_.begin) markers_.begin(markers_.context, stage);
    }
    void mark_end() const {
        if (markers_.end) markers_.end(markers_.context);
    }

    gl::ObjectTracker* tracker_;
    PassMarkers markers_;
    int gl_version_ = 0;            // the context's, e.g. 45; 0 until the first apply
    bool compute_refused_ = false;  // a compute stage did not build: full-screen ones instead
    std::array<StagePrograms, 2> stages_;   // by StagePath
    StagePath path_ = StagePath::fragment;  // this apply's
    StageTrial trial_;
    StageClock clock_;
    TrialKey trial_key_;
    int trial_issued_ = 0;  // trial frames run so far
    int trial_read_ = 0;    // trial frames whose times have been read back
    int decisions_ = 0;
    gl::Program composite_, moments_program_;
    gl::VertexArray empty_vertex_array_;
    std::array<Target, 2> targets_;
    const gl::Texture* result_ = nullptr;
    int target_width_ = 0, target_height_ = 0;
    Target moments_;
    int moments_width_ = 0, moments_height_ = 0;
};

}  // namespace nq::npr::obscurance
