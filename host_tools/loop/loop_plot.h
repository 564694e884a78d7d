#pragma once
// Scatter plots for the loop report, drawn with OpenCV (PNG).
#include <string>
#include <vector>

namespace icacam::host::loop {

struct Series {
    std::vector<double> x, y;
    unsigned colour = 0x1f77b4; // RGB
    std::string label;
    bool line = false; // draw as a polyline (sorted by x) instead of points
};

// xTicks: names for categorical axes (x values 0, 1, ... map to these); empty for numeric.
bool scatterPlot(const std::string &path, const std::string &title, const std::string &xLabel,
                 const std::string &yLabel, const std::vector<Series> &series,
                 const std::vector<std::string> &xTicks = {}, bool identity = false);

} // namespace icacam::host::loop
