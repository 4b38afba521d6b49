#include "ReportChart.h"

#include "Options.h"
#include "SceneSetup.h"

#include "vtkAxis.h"
#include "vtkChartLegend.h"
#include "vtkChartMatrix.h"
#include "vtkChartXY.h"
#include "vtkContextScene.h"
#include "vtkContextView.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPen.h"
#include "vtkPlot.h"
#include "vtkPlotPoints.h"
#include "vtkRenderer.h"
#include "vtkTable.h"
#include "vtkTextProperty.h"
#include "vtkVector.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace deepshadow
{
namespace tool
{
namespace
{
// Marker colours, in the order series first appear (colour-blind-friendly palette).
const unsigned char Palette[][3] = { { 0, 114, 178 }, { 230, 159, 0 }, { 0, 158, 115 },
  { 204, 121, 167 }, { 86, 180, 233 }, { 213, 94, 0 }, { 240, 228, 66 }, { 0, 0, 0 },
  { 120, 120, 120 }, { 150, 60, 200 }, { 120, 200, 60 }, { 160, 100, 40 } };
const int Markers[] = { vtkPlotPoints::CIRCLE, vtkPlotPoints::SQUARE, vtkPlotPoints::DIAMOND,
  vtkPlotPoints::PLUS, vtkPlotPoints::CROSS };

vtkSmartPointer<vtkTable> MakeTable(const char* xName, const char* yName)
{
  auto table = vtkSmartPointer<vtkTable>::New();
  vtkNew<vtkDoubleArray> x, y;
  x->SetName(xName);
  y->SetName(yName);
  table->AddColumn(x);
  table->AddColumn(y);
  return table;
}

void AddRow(vtkTable* table, double x, double y)
{
  table->InsertNextBlankRow();
  const vtkIdType row = table->GetNumberOfRows() - 1;
  table->SetValue(row, 0, x);
  table->SetValue(row, 1, y);
}

void FillChart(vtkChartXY* chart, const ChartPanel& panel, std::map<std::string, size_t>& styles)
{
  chart->SetTitle(panel.Title);
  chart->GetTitleProperties()->SetFontSize(15);
  chart->SetShowLegend(true);
  chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::RIGHT);
  chart->GetLegend()->SetVerticalAlignment(vtkChartLegend::TOP);
  chart->GetLegend()->SetLabelSize(11);
  for (int a : { vtkAxis::BOTTOM, vtkAxis::LEFT })
  {
    vtkAxis* axis = chart->GetAxis(a);
    axis->SetLogScale(true);
    axis->SetTitle(a == vtkAxis::BOTTOM ? panel.TimeLabel : panel.ErrorLabel);
    axis->GetTitleProperties()->SetFontSize(13);
    axis->GetLabelProperties()->SetFontSize(11);
  }

  // The Pareto front as a staircase (each point is best until the next faster-and-better one).
  const std::vector<size_t> front = ParetoFront(panel.Points);
  if (!front.empty())
  {
    auto table = MakeTable("time", "Pareto front");
    for (size_t i = 0; i < front.size(); ++i)
    {
      const ChartPoint& p = panel.Points[front[i]];
      if (i > 0)
      {
        AddRow(table, p.Time, panel.Points[front[i - 1]].Error);
      }
      AddRow(table, p.Time, p.Error);
    }
    vtkPlot* line = chart->AddPlot(vtkChart::LINE);
    line->SetInputData(table, 0, 1);
    line->SetColor(0, 0, 0, 255);
    line->SetWidth(1.5);
    line->GetPen()->SetLineType(vtkPen::DASH_LINE);
  }

  std::vector<std::string> order;
  std::map<std::string, vtkSmartPointer<vtkTable>> tables;
  for (const ChartPoint& p : panel.Points)
  {
    if (!tables.count(p.Series))
    {
      tables[p.Series] = MakeTable("time", p.Series.c_str());
      order.push_back(p.Series);
    }
    AddRow(tables[p.Series], p.Time, p.Error);
  }
  for (const std::string& series : order)
  {
    const size_t style = styles.emplace(series, styles.size()).first->second;
    auto* points = vtkPlotPoints::SafeDownCast(chart->AddPlot(vtkChart::POINTS));
    points->SetInputData(tables[series], 0, 1);
    const unsigned char* c = Palette[style % (sizeof(Palette) / sizeof(Palette[0]))];
    points->SetColor(c[0], c[1], c[2], 255);
    points->SetMarkerStyle(Markers[style % (sizeof(Markers) / sizeof(Markers[0]))]);
    points->SetMarkerSize(9.0);
  }
}
}

std::vector<size_t> ParetoFront(const std::vector<ChartPoint>& points)
{
  std::vector<size_t> order(points.size());
  for (size_t i = 0; i < order.size(); ++i)
  {
    order[i] = i;
  }
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return points[a].Time != points[b].Time ? points[a].Time < points[b].Time
                                            : points[a].Error < points[b].Error;
  });
  // Sweep by increasing time: a point is on the front if it beats every faster one's error.
  std::vector<size_t> front;
  double best = HUGE_VAL;
  for (size_t i : order)
  {
    if (points[i].Error < best)
    {
      front.push_back(i);
      best = points[i].Error;
    }
  }
  return front;
}

void WriteErrorVsTimeChart(const std::string& path, const std::vector<ChartPanel>& panels)
{
  vtkNew<vtkDeepShadowRenderWindow> window;
  window->SetSize(560 * static_cast<int>(panels.size()), 480);
  vtkNew<vtkContextView> view;
  view->SetRenderWindow(window);
  view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
  vtkNew<vtkChartMatrix> matrix;
  matrix->SetSize(vtkVector2i(static_cast<int>(panels.size()), 1));
  matrix->SetGutter(vtkVector2f(70.0f, 60.0f));
  view->GetScene()->AddItem(matrix);
  std::map<std::string, size_t> styles; // the same technique has the same marker everywhere
  for (size_t i = 0; i < panels.size(); ++i)
  {
    auto* chart = vtkChartXY::SafeDownCast(matrix->GetChart(vtkVector2i(static_cast<int>(i), 0)));
    FillChart(chart, panels[i], styles);
  }
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  WritePNG(grab->GetOutput(), path);
}

}
}
