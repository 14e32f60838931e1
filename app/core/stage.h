// A stage of the pipeline (DESIGN.md §3): declares its outputs and parameters once and
// writes its outputs into the Frame. The UI, `--set`, export, lessons and tests all read
// these declarations; no stage has UI or CLI code of its own.
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
};

struct Output {
  std::string name;  // "visibility"; addressed as "stage.visibility"
  std::string doc;
  GLenum format;
  std::vector<std::string> channels;  // EXR channel names, one per texture channel
  DisplayHint display;
};

class Stage {
public:
  virtual ~Stage() = default;
  virtual std::string name() const = 0;           // "classify"
  virtual std::string summary() const = 0;        // one sentence for the UI
  virtual std::string thesisSection() const = 0;  // "3.6", "" where none
  virtual void run(Frame& frame) = 0;             // reads inputs by name, writes its outputs

  const std::vector<Output>& outputs() const { return outputs_; }
  std::vector<Param>& params() { return params_; }
  const std::vector<Param>& params() const { return params_; }
  Param& param(const std::string& key);  // throws std::out_of_range naming the valid keys
  const Param& param(const std::string& key) const;
  const Output& output(const std::string& name) const;

protected:
  std::vector<Output> outputs_;
  std::vector<Param> params_;
};
