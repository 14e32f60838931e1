// A stage of the pipeline (docs/design.md#stage-contract; after Falcor's render passes): it
// declares its inputs, outputs, parameters and capabilities once, and writes its outputs into the Frame. The
// registry (stages/registry.cpp) wires input slots to other stages' outputs; the pipeline
// checks the graph, orders it and runs only what the requested outputs depend on. The UI,
// `--set`, export, bench, lessons and tests all read these declarations; no stage has UI or
// CLI code of its own, and no stage reads another stage's parameters.
#pragma once
#include <epoxy/gl.h>

#include <string>
#include <vector>

#include "core/param.h"

struct Frame;

enum class Colormap { Gray, Perceptual, Diverging, Categorical };

// How a view shows an output by default (and how the PNG export renders it).
struct DisplayHint {
  int channel = -1;  // -1: show RGB as colour; else this channel as a single value
  float black = 0, white = 1;
  Colormap colormap = Colormap::Gray;
  // Errors and counts whose spread depends on the scene: views and annotated exports start
  // from the data's range instead (robustRange, app/io/colormap.h; symmetric when diverging),
  // black..white above is used only where no value is written.
  bool rangeFromData = false;
};

// What an output is to the rest of the program. A *shadow method's visibility* is eye-sized,
// GL_R32F, values in [0, 1]: composite, error, bench and the window list exactly these.
// A *ground truth* is a visibility other methods are measured against. A *hierarchy* is
// min/max light depths over regions of the light layers, RGBA32F (the trace's choice of
// N-buffer or min-max mipmap).
enum Role : unsigned {
  kRoleNone = 0, kRoleShadowMethod = 1, kRoleGroundTruth = 2, kRoleHierarchy = 4
};

// Format of an output or input that is a storage buffer rather than a texture.
constexpr GLenum kBufferFormat = GL_BUFFER;

struct Output {
  std::string name;  // "visibility"; addressed as "stage.visibility"
  std::string doc;
  GLenum format;                      // texture internal format, or kBufferFormat
  std::vector<std::string> channels;  // EXR channel names, one per texture channel
  DisplayHint display;
  unsigned roles = kRoleNone;  // Role bits

  bool isBuffer() const { return format == kBufferFormat; }
  // A storage buffer handed to later stages (not a view, not exported).
  static Output buffer(std::string name, std::string doc) {
    return {std::move(name), std::move(doc), kBufferFormat, {}, {}, kRoleNone};
  }
};

struct Input {
  std::string name;  // slot name, "visibility"; the registry wires it to "producer.output"
  std::string doc;
  GLenum format = 0;  // expected format (0: any texture; kBufferFormat: a buffer)
  // A *choice* slot is wired to one of the outputs carrying `chooseRole`, selected by this
  // stage's Enum parameter `choiceParam` (composite.shadow, error.method). The pipeline fills
  // that parameter's options with the producers' stage names, in registry order, plus "none"
  // when `allowNone`; `defaultChoice` names the initial option. A `choiceParam` of the form
  // "stage.key" *follows* another stage's choice instead (classify's hierarchy follows
  // trace.hierarchy: one switch, and the stage that is not chosen does not run); the
  // pipeline checks that both list the same producers, and the stage itself still reads
  // no other stage's parameter.
  unsigned chooseRole = kRoleNone;
  std::string choiceParam;
  std::string defaultChoice;
  bool allowNone = false;
  // A choice whose parameter allows `auto` is decided each frame by the owning stage's
  // chooseAuto() right after stage `decidedAfter` has run (the rule may read what that stage
  // wrote into the frame: trace.hierarchy reads the light's map size). Until then the choice
  // leads nowhere, so no candidate runs before the decision; the pipeline checks that the
  // choosing stage and every slot following the choice depend on `decidedAfter` through
  // fixed edges, so none of them runs before it either.
  std::string decidedAfter;

  bool isChoice() const { return chooseRole != kRoleNone; }
  bool followsChoice() const { return isChoice() && choiceParam.find('.') != std::string::npos; }
  static Input texture(std::string name, std::string doc, GLenum format = 0) {
    Input input;
    input.name = std::move(name), input.doc = std::move(doc), input.format = format;
    return input;
  }
  static Input buffer(std::string name, std::string doc) {
    return texture(std::move(name), std::move(doc), kBufferFormat);
  }
  static Input choice(std::string name, std::string doc, unsigned role, std::string param,
                      std::string defaultChoice, bool allowNone) {
    Input input = texture(std::move(name), std::move(doc), GL_R32F);
    input.chooseRole = role, input.choiceParam = std::move(param);
    input.defaultChoice = std::move(defaultChoice), input.allowNone = allowNone;
    return input;
  }
};

// What a stage offers the window beyond showing its outputs, declared once beside its inputs,
// outputs and parameters (`capabilities_`). The window finds the stages it drives by these
// bits, never by a stage's name or by which parameters it happens to declare; each bit is a
// promise of the parameters and outputs named below, which the pipeline checks when it is
// built (checkCapabilities; decision 105).
enum Capability : unsigned {
  kCapabilityNone = 0,
  // An eye pick becomes the stage's picked pixel: Int parameters pick_x, pick_y (image
  // column, row from the top; -1: none). raster4d (pickedMask), ssm (pickedLight).
  kCapabilityPicksEyePixel = 1,
  // A pick in a view of the stage's own light-space maps becomes its picked map texel: Int
  // parameters patch_x, patch_y (GL texel, row 0 at the bottom) on maps of Int parameter
  // `resolution` texels per side. ssm (pickedFootprint).
  kCapabilityPicksMapTexel = 2,
  // Every step of the rays of one eye pixel is recorded for the trace panel: Int parameters
  // record_x, record_y (image column, row from the top; -1: none) and `rays` (per side), its
  // input slots `near` and `far` (the layers the rays are drawn over). trace.
  kCapabilityRecordsRays = 4,
  // The picked pixel's mask over the light's m x m sample grid, drawn on the light in the
  // 3D view: a square texture output `pickedMask`; implies kCapabilityPicksEyePixel. raster4d.
  kCapabilityPickedLightMask = 8,
};

// The parameter keys and outputs the capabilities promise.
inline constexpr const char* kPickXParam = "pick_x";
inline constexpr const char* kPickYParam = "pick_y";
inline constexpr const char* kPatchXParam = "patch_x";
inline constexpr const char* kPatchYParam = "patch_y";
inline constexpr const char* kMapResolutionParam = "resolution";
inline constexpr const char* kRecordXParam = "record_x";
inline constexpr const char* kRecordYParam = "record_y";
inline constexpr const char* kRaysParam = "rays";
inline constexpr const char* kPickedLightMaskOutput = "pickedMask";

// What an `auto` choice took this frame, and why (one sentence for the inspector).
struct AutoChoice {
  std::string option;
  std::string reason;
};

class Stage {
public:
  virtual ~Stage() = default;
  virtual std::string name() const = 0;           // "classify"
  virtual std::string summary() const = 0;        // one sentence for the UI
  // Where it comes from: "thesis §3.6, Eq 3.3", "Atty et al. 2006 §3"; "" where none.
  virtual std::string thesisSection() const = 0;
  virtual void run(Frame& frame) = 0;             // reads its inputs, writes its outputs
  // The option an `auto` choice parameter `key` takes this frame (see Input::decidedAfter).
  // Only stages that declare such a parameter override it; the default throws.
  virtual AutoChoice chooseAuto(const std::string& key, const Frame& frame) const;

  const std::vector<Input>& inputs() const { return inputs_; }
  const std::vector<Output>& outputs() const { return outputs_; }
  std::vector<Param>& params() { return params_; }
  const std::vector<Param>& params() const { return params_; }
  Param& param(const std::string& key);  // throws std::out_of_range naming the valid keys
  const Param& param(const std::string& key) const;
  const Output& output(const std::string& name) const;
  const Input& input(const std::string& name) const;
  unsigned capabilities() const { return capabilities_; }  // Capability bits
  bool can(Capability capability) const { return (capabilities_ & capability) != 0; }

protected:
  std::vector<Input> inputs_;
  std::vector<Output> outputs_;
  std::vector<Param> params_;
  unsigned capabilities_ = kCapabilityNone;
};

// Throws std::invalid_argument naming the stage, the capability and what it lacks when a
// declared capability's parameters (with their types) or outputs are missing.
void checkCapabilities(const Stage& stage);
