#pragma once
/// @file The two-dimensional views of a joint's film fields, computed from FieldFrames for
/// FilmMapWidget: the unrolled map of one frame (circumferential angle × axial position, every
/// node at its place with its value) and the crank-angle map (circumferential angle × crank
/// angle over the cycle, the largest value along each axial line — the smallest for the film
/// thickness). Values in display units (FieldArrayInfo::scale), angles in degrees, lengths in mm.
#include <QString>
#include <utility>
#include <vector>

#include "ui/charts/film_map_widget.hpp"
#include "ui/fields/field_frames.hpp"

namespace filmdyn::ui {

/// The joint's name for people: "Piston skirt", "Big-end bearing".
QString JointTitle(const JointFieldFrames& joint);

/// Why a joint's frames lack an array, for its pane in place of the views: the fluid fraction of
/// a joint solved with Reynolds cavitation (naming the case field that chooses JFO, from core's
/// schema), or an array its stored fields do not have.
QString MissingArrayText(const JointFieldFrames& joint, const FieldArrayInfo& info);

/// Lowest and highest value of an array over every frame of a joint, in display units, nodes
/// inside the intervals without film left out; {+inf, −inf} when there is none.
std::pair<double, double> ValueRange(const JointFieldFrames& joint, const FieldArrayInfo& info);

/// The body-frame angle [°, within [0, 360) for periodic joints] of node column i in frame k.
double ColumnAngleDeg(const JointFieldFrames& joint, size_t column, size_t frame);

/// The unrolled map of frame `frame` (requires joint.HasGrid()). Each node of the mesh is a node
/// of the map with its own value; a periodic joint whose columns are turned (the big end in the
/// rod frame) gets the two edge lines 0° and 360° added, interpolated between their neighbours.
FilmMapData UnrolledMap(const JointFieldFrames& joint, size_t frame, const FieldArrayInfo& info);

/// The crank-angle map of joint `joint` (requires HasGrid()): rows are the frames sorted by crank
/// angle, each row the largest value along every axial line (smallest when
/// info.minimum_matters). The skirt's columns are its own angle lines; a turned periodic joint
/// is resampled (linearly, periodically) on evenly spaced body-frame angles, one per column.
FilmMapData CrankAngleMap(const FieldFrames& frames, size_t joint, const FieldArrayInfo& info);

/// The extreme of frame `frame` along each axial line of column i, in display units (the
/// crank-angle map's row before resampling).
std::vector<double> ColumnExtremes(const JointFieldFrames& joint, size_t frame,
                                   const FieldArrayInfo& info);

}  // namespace filmdyn::ui
