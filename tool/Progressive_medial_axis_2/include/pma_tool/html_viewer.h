// Copyright (c) 2026 The Progressive_medial_axis_2 authors.
// All rights reserved.
//
// This file is part of the command-line tool of Progressive_medial_axis_2
// (not of the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The progressive viewer: one self-contained HTML page (no network access:
// no script, style or font is loaded from anywhere) with the SVG pictures
// of progressive steps, a slider over them, pan (drag) and zoom (wheel),
// and the step number and vertex count of the shown step.  The page opens
// at the last frame, or at frame K with `#frame=K` in its address.

#ifndef PMA_TOOL_HTML_VIEWER_H
#define PMA_TOOL_HTML_VIEWER_H

#include <nlohmann/json.hpp>

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace pma_tool {

/// One picture of the viewer: an SVG document (as write_svg() writes it,
/// every frame in the same frame of coordinates) and what the page shows
/// with it.
struct Html_frame {
  std::size_t step = 0, steps = 0;    // step shown, steps of the whole run
  std::size_t vertices = 0;           // vertices of the shape at that step
  std::size_t curves = 0;             // medial curves
  std::string svg;
};

/// Writes the viewer page of `frames` (in order of steps) titled `title`.
inline void write_html_viewer(std::ostream& out, const std::vector<Html_frame>& frames, const std::string& title)
{
  nlohmann::json data = nlohmann::json::array();
  for(const Html_frame& f : frames)
    data.push_back({{"step", f.step}, {"steps", f.steps}, {"vertices", f.vertices}, {"curves", f.curves}, {"svg", f.svg}});
  // JSON inside a <script> element: "</" would end it
  auto script_json = [](const nlohmann::json& j) {
    std::string text = j.dump();
    for(std::size_t p = 0; (p = text.find("</", p)) != std::string::npos; p += 3) text.replace(p, 2, "<\\/");
    return text;
  };
  const std::string json = script_json(data), safe_title = script_json(title);
  out << R"(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>progressive medial axis</title>
<style>
  html, body { margin: 0; height: 100%; font-family: sans-serif; background: #fafafa; }
  #bar { display: flex; gap: 1em; align-items: center; padding: 0.5em 1em; background: #fff; border-bottom: 1px solid #ccc; }
  #slider { flex: 1; }
  #info { white-space: nowrap; font-size: 0.9em; font-variant-numeric: tabular-nums; }
  #title, #reset { white-space: nowrap; }
  #view { position: absolute; top: 3em; bottom: 0; left: 0; right: 0; overflow: hidden; cursor: grab; }
  #view svg { width: 100%; height: 100%; display: block; }
</style>
</head>
<body>
<div id="bar">
  <strong id="title"></strong>
  <input type="range" id="slider" min="0" value="0" step="1" aria-label="progressive step">
  <span id="info"></span>
  <button id="reset" type="button">reset view</button>
</div>
<div id="view"></div>
<script>
"use strict";
const frames = )" << json << R"(;
const title = )" << safe_title << R"(;
const slider = document.getElementById("slider");
const view = document.getElementById("view");
const info = document.getElementById("info");
document.getElementById("title").textContent = title;
document.title = title + " - progressive medial axis";
slider.max = String(frames.length - 1);
let box = null;     // the shown part of the picture: [x, y, w, h] in SVG units
let full = null;    // the whole picture
function svgElement() { return view.querySelector("svg"); }
function applyBox() { const s = svgElement(); if(s && box) s.setAttribute("viewBox", box.join(" ")); }
function show(k) {
  const f = frames[k];
  view.innerHTML = f.svg;
  const s = svgElement();
  s.removeAttribute("width");
  s.removeAttribute("height");
  s.setAttribute("preserveAspectRatio", "xMidYMid meet");
  if(!full) { full = s.getAttribute("viewBox").split(/\s+/).map(Number); box = full.slice(); }
  applyBox();
  info.textContent = "frame " + (k + 1) + " of " + frames.length + ": step " + f.step + " of " + f.steps +
                     ", " + f.vertices + " vertices, " + f.curves + " medial curves";
}
// the picture's units per screen pixel
function unitsPerPixel() {
  const r = view.getBoundingClientRect();
  return Math.max(box[2] / r.width, box[3] / r.height);
}
view.addEventListener("wheel", (e) => {
  e.preventDefault();
  const r = view.getBoundingClientRect(), u = unitsPerPixel();
  // the picture point under the mouse stays in place
  const cx = box[0] + box[2] / 2 + (e.clientX - r.left - r.width / 2) * u;
  const cy = box[1] + box[3] / 2 + (e.clientY - r.top - r.height / 2) * u;
  const z = Math.exp(Math.sign(e.deltaY) * 0.15);
  box = [cx - (cx - box[0]) * z, cy - (cy - box[1]) * z, box[2] * z, box[3] * z];
  applyBox();
}, { passive: false });
let drag = null;
view.addEventListener("pointerdown", (e) => { drag = [e.clientX, e.clientY]; view.setPointerCapture(e.pointerId); view.style.cursor = "grabbing"; });
view.addEventListener("pointermove", (e) => {
  if(!drag) return;
  const u = unitsPerPixel();
  box[0] -= (e.clientX - drag[0]) * u;
  box[1] -= (e.clientY - drag[1]) * u;
  drag = [e.clientX, e.clientY];
  applyBox();
});
view.addEventListener("pointerup", () => { drag = null; view.style.cursor = "grab"; });
document.getElementById("reset").addEventListener("click", () => { box = full.slice(); applyBox(); });
slider.addEventListener("input", () => show(Number(slider.value)));
const m = /frame=(\d+)/.exec(location.hash);
const first = m ? Math.min(Number(m[1]), frames.length - 1) : frames.length - 1;
slider.value = String(first);
show(first);
</script>
</body>
</html>
)";
}

} // namespace pma_tool

#endif // PMA_TOOL_HTML_VIEWER_H
