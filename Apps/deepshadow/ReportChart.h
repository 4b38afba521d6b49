// The report's error-against-time charts: VTK's own charts (vtkChartXY in a vtkChartMatrix)
// rendered headless into a PNG, one marker series per technique, the Pareto front drawn.
#ifndef deepshadow_tool_ReportChart_h
#define deepshadow_tool_ReportChart_h

#include <string>
#include <vector>

namespace deepshadow
{
namespace tool
{

struct ChartPoint
{
  std::string Series; // the technique: one marker series each
  double Time = 0.0;  // x, > 0 (log axis)
  double Error = 0.0; // y, > 0 (log axis)
};

struct ChartPanel
{
  std::string Title;
  std::string TimeLabel;
  std::string ErrorLabel;
  std::vector<ChartPoint> Points;
};

/**
 * Indices of the points on the Pareto front of (Time, Error), both minimised: no other point
 * is at least as fast and as accurate and better in one. Sorted by time.
 */
std::vector<size_t> ParetoFront(const std::vector<ChartPoint>& points);

/** Writes the panels side by side into a PNG; throws UsageError if it cannot. */
void WriteErrorVsTimeChart(const std::string& path, const std::vector<ChartPanel>& panels);

}
}
#endif
