// The order of bricks toward a light and the product of the bricks in front
// (Core/Shadows/Bricks.h): what a brick drawn by one MPI rank multiplies into its lookups.
#include "Core/Shadows/Bricks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <condition_variable>
#include <map>
#include <mutex>
#include <random>
#include <thread>
#include <tuple>

using namespace deepshadow;

namespace
{
Light Directional(const glm::dvec3& travel)
{
  Light light;
  light.Positional = false;
  light.Position = -travel;
  light.FocalPoint = glm::dvec3(0.0);
  return light;
}

Light Positional(const glm::dvec3& at)
{
  Light light;
  light.Positional = true;
  light.Position = at;
  return light;
}

// A kd partition of the box [0, 4]^3 into `bricks` boxes (as ParaView's ordered compositing
// cuts a volume): the largest box is split across its longest axis at a random place.
std::vector<BrickBox> KdBricks(int bricks, std::mt19937& random)
{
  std::vector<BrickBox> boxes{ BrickBox{ glm::dvec3(0.0), glm::dvec3(4.0) } };
  std::uniform_real_distribution<double> where(0.3, 0.7);
  while (static_cast<int>(boxes.size()) < bricks)
  {
    auto largest = std::max_element(boxes.begin(), boxes.end(), [](const BrickBox& a, const BrickBox& b) {
      const glm::dvec3 da = a.Max - a.Min, db = b.Max - b.Min;
      return da.x * da.y * da.z < db.x * db.y * db.z;
    });
    const glm::dvec3 size = largest->Max - largest->Min;
    const int axis = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
    BrickBox high = *largest;
    const double cut = largest->Min[axis] + where(random) * size[axis];
    largest->Max[axis] = cut;
    high.Min[axis] = cut;
    boxes.push_back(high);
  }
  return boxes;
}

// Messages between threads, one per brick, as MPI's blocking send and receive behave: a
// send waits until its receiver has taken it.
class Mailboxes
{
public:
  bool Message(int self, int to, const std::vector<float>& send, int from, std::vector<float>& received,
    bool sendFirst, int tag)
  {
    if (sendFirst && to >= 0)
    {
      this->Send(self, to, tag, send);
    }
    if (from >= 0)
    {
      this->Receive(from, self, tag, received);
    }
    if (!sendFirst && to >= 0)
    {
      this->Send(self, to, tag, send);
    }
    return true;
  }
  std::map<int, long long> ReceivedValues; // by brick

private:
  void Send(int from, int to, int tag, const std::vector<float>& values)
  {
    std::unique_lock<std::mutex> lock(this->Mutex);
    const auto key = std::make_tuple(from, to, tag);
    this->Posted[key] = values;
    this->Changed.notify_all();
    this->Changed.wait(lock, [&] { return this->Posted.count(key) == 0; });
  }
  void Receive(int from, int to, int tag, std::vector<float>& values)
  {
    std::unique_lock<std::mutex> lock(this->Mutex);
    const auto key = std::make_tuple(from, to, tag);
    this->Changed.wait(lock, [&] { return this->Posted.count(key) != 0; });
    values = this->Posted[key];
    this->Posted.erase(key);
    this->ReceivedValues[to] += static_cast<long long>(values.size());
    this->Changed.notify_all();
  }
  std::mutex Mutex;
  std::condition_variable Changed;
  std::map<std::tuple<int, int, int>, std::vector<float>> Posted;
};

// Two bricks sharing the face z = 0: below [0,1]^2 x [-1, 0], above [0,1]^2 x [0, 1].
const BrickBox Below{ { 0.0, 0.0, -1.0 }, { 1.0, 1.0, 0.0 } };
const BrickBox Above{ { 0.0, 0.0, 0.0 }, { 1.0, 1.0, 1.0 } };
}

TEST(Bricks, DirectionalLightOrdersBricksAlongItsTravel)
{
  // Light from above (travelling -z): the upper brick is crossed first.
  EXPECT_EQ(OrderTowardLight(Above, Below, Directional({ 0.0, 0.0, -1.0 }), 1e-9), BrickOrder::First);
  EXPECT_EQ(OrderTowardLight(Below, Above, Directional({ 0.0, 0.0, -1.0 }), 1e-9), BrickOrder::Last);
  // From below, the other way; slanted rays still cross the shared face from above.
  EXPECT_EQ(OrderTowardLight(Above, Below, Directional({ 0.0, 0.0, 1.0 }), 1e-9), BrickOrder::Last);
  EXPECT_EQ(OrderTowardLight(Above, Below, Directional({ 0.7, -0.3, -0.2 }), 1e-9), BrickOrder::First);
  // Rays parallel to the shared face cross no brick after the other.
  EXPECT_EQ(OrderTowardLight(Above, Below, Directional({ 1.0, 0.0, 0.0 }), 1e-9), BrickOrder::Unordered);
}

TEST(Bricks, PositionalLightOrdersBricksBySideOfTheLight)
{
  EXPECT_EQ(OrderTowardLight(Above, Below, Positional({ 0.5, 0.5, 5.0 }), 1e-9), BrickOrder::First);
  EXPECT_EQ(OrderTowardLight(Above, Below, Positional({ 0.5, 0.5, -5.0 }), 1e-9), BrickOrder::Last);
  // A light inside the upper brick still lights the lower one through it.
  EXPECT_EQ(OrderTowardLight(Above, Below, Positional({ 0.5, 0.5, 0.5 }), 1e-9), BrickOrder::First);
  // On the shared plane: no ray passes from one into the other.
  EXPECT_EQ(OrderTowardLight(Above, Below, Positional({ 5.0, 0.5, 0.0 }), 1e-9), BrickOrder::Unordered);
}

TEST(Bricks, OverlapIsToleratedOnlyUpToTheTolerance)
{
  const BrickBox lower{ { 0.0, 0.0, -1.0 }, { 1.0, 1.0, 1e-7 } }; // float rounding of a shared face
  EXPECT_FALSE(BricksOverlap(lower, Above, 1e-6));
  EXPECT_EQ(OrderTowardLight(Above, lower, Directional({ 0.0, 0.0, -1.0 }), 1e-6), BrickOrder::First);
  const BrickBox ghost{ { 0.0, 0.0, -1.0 }, { 1.0, 1.0, 0.1 } }; // one ghost layer deep
  EXPECT_TRUE(BricksOverlap(ghost, Above, 1e-6));
  EXPECT_EQ(OrderTowardLight(Above, ghost, Directional({ 0.0, 0.0, -1.0 }), 1e-6), BrickOrder::Unordered);
}

TEST(Bricks, UpstreamIsTheProductOfTheBricksInFront)
{
  // Three bricks stacked along z, each a homogeneous slab: one texel, one channel. Light from
  // above: Beer-Lambert through the bricks above is the product of their transmittances.
  const std::vector<BrickBox> boxes{ { { 0, 0, 0 }, { 1, 1, 1 } }, { { 0, 0, 1 }, { 1, 1, 2 } },
    { { 0, 0, 2 }, { 1, 1, 3 } } };
  const double sigma[3] = { 0.5, 1.0, 2.0 };
  std::vector<float> totals;
  for (double s : sigma)
  {
    totals.push_back(static_cast<float>(std::exp(-s)));
  }
  const Light fromAbove = Directional({ 0.0, 0.0, -1.0 });
  bool overlapping = true;
  EXPECT_NEAR(UpstreamTransmittance(totals, 1, 0, boxes, fromAbove, 1e-9, overlapping)[0], std::exp(-3.0), 1e-6);
  EXPECT_FALSE(overlapping);
  EXPECT_NEAR(UpstreamTransmittance(totals, 1, 1, boxes, fromAbove, 1e-9, overlapping)[0], std::exp(-2.0), 1e-6);
  EXPECT_EQ(UpstreamTransmittance(totals, 1, 2, boxes, fromAbove, 1e-9, overlapping)[0], 1.0f);
  const Light fromBelow = Directional({ 0.0, 0.0, 1.0 });
  EXPECT_NEAR(UpstreamTransmittance(totals, 1, 2, boxes, fromBelow, 1e-9, overlapping)[0], std::exp(-1.5), 1e-6);
  // A brick that is not there (an empty rank: invalid box) is left out.
  std::vector<BrickBox> withEmpty = boxes;
  withEmpty[1] = BrickBox{};
  EXPECT_NEAR(UpstreamTransmittance(totals, 1, 0, withEmpty, fromAbove, 1e-9, overlapping)[0], std::exp(-2.0), 1e-6);
}

TEST(Bricks, UnionIgnoresMissingBricks)
{
  const BrickBox both = Below.Union(BrickBox{}).Union(Above);
  EXPECT_EQ(both.Min, glm::dvec3(0.0, 0.0, -1.0));
  EXPECT_EQ(both.Max, glm::dvec3(1.0, 1.0, 1.0));
  EXPECT_FALSE(BrickBox{}.IsValid());
}

// Where a ray origin + t direction (t > 0) is inside `box`: [enter, leave], empty if enter >= leave.
std::pair<double, double> Crossing(const glm::dvec3& origin, const glm::dvec3& direction, const BrickBox& box)
{
  double enter = 0.0, leave = 1e300;
  for (int axis = 0; axis < 3; ++axis)
  {
    if (direction[axis] == 0.0)
    {
      if (origin[axis] < box.Min[axis] || origin[axis] > box.Max[axis])
      {
        return { 0.0, 0.0 };
      }
      continue;
    }
    double a = (box.Min[axis] - origin[axis]) / direction[axis];
    double b = (box.Max[axis] - origin[axis]) / direction[axis];
    enter = std::max(enter, std::min(a, b));
    leave = std::min(leave, std::max(a, b));
  }
  return { enter, leave };
}

TEST(Bricks, ScanAndGatherAreBeerLambertAlongEveryRay)
{
  // A homogeneous medium cut into a kd partition of bricks, each brick a thread. A light
  // texel is a ray: a brick's total there is exp(-sigma x its length in the brick). Along
  // every ray, what a brick it crosses receives must be exp(-sigma x the length before it):
  // from the gather (UpstreamTransmittance) and from the scan along LightOrder, whose every
  // brick receives at most ceil(log2 bricks) messages.
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double sigma = 0.4;
  const int rays = 64;
  for (int bricks : { 1, 2, 3, 5, 8, 13, 32 })
  {
    const std::vector<BrickBox> boxes = KdBricks(bricks, random);
    for (int trial = 0; trial < 6; ++trial)
    {
      const glm::dvec3 v(unit(random), unit(random), unit(random));
      const bool positional = trial % 2 == 0;
      // A positional light inside the volume on every other such trial.
      const Light light = positional ? Positional(2.0 + (trial % 4 ? 1.2 : 4.0) * v) : Directional(v);
      std::vector<glm::dvec3> origins, directions;
      for (int r = 0; r < rays; ++r)
      {
        const glm::dvec3 target(2.0 + 2.0 * unit(random), 2.0 + 2.0 * unit(random), 2.0 + 2.0 * unit(random));
        const glm::dvec3 direction =
          positional ? glm::normalize(target - light.Position) : glm::normalize(light.FocalPoint - light.Position);
        origins.push_back(positional ? light.Position : target - 100.0 * direction);
        directions.push_back(direction);
      }
      std::vector<float> totals(static_cast<size_t>(rays * bricks));
      std::vector<std::pair<double, double>> crossings(totals.size());
      for (int b = 0; b < bricks; ++b)
      {
        for (int r = 0; r < rays; ++r)
        {
          const auto c = Crossing(origins[r], directions[r], boxes[b]);
          crossings[b * rays + r] = c;
          totals[b * rays + r] = static_cast<float>(std::exp(-sigma * std::max(0.0, c.second - c.first)));
        }
      }
      const std::vector<int> order = LightOrder(boxes, light, 1e-9);
      ASSERT_EQ(order.size(), boxes.size()) << bricks << " bricks: no order";
      Mailboxes mail;
      std::vector<std::vector<float>> scanned(static_cast<size_t>(bricks));
      std::vector<int> succeeded(static_cast<size_t>(bricks), 0);
      std::vector<std::thread> threads;
      for (int b = 0; b < bricks; ++b)
      {
        threads.emplace_back([&, b] {
          const std::vector<float> local(totals.begin() + b * rays, totals.begin() + (b + 1) * rays);
          const ScanMessage message = [&mail, b](int to, const std::vector<float>& send, int from,
                                        std::vector<float>& received, bool sendFirst, int tag) {
            return mail.Message(b, to, send, from, received, sendFirst, tag);
          };
          succeeded[static_cast<size_t>(b)] =
            ExclusiveProductScan(order, b, local, 100, message, scanned[static_cast<size_t>(b)]) ? 1 : 0;
        });
      }
      for (std::thread& thread : threads)
      {
        thread.join();
      }
      int checked = 0;
      for (int b = 0; b < bricks; ++b)
      {
        ASSERT_TRUE(succeeded[static_cast<size_t>(b)]);
        bool overlapping = false;
        const std::vector<float> gathered = UpstreamTransmittance(totals, rays, b, boxes, light, 1e-9, overlapping);
        EXPECT_LE(mail.ReceivedValues[b], static_cast<long long>(ScanRounds(bricks) * rays));
        for (int r = 0; r < rays; ++r)
        {
          const auto mine = crossings[b * rays + r];
          if (mine.second - mine.first < 1e-6)
          {
            continue; // this ray does not light the brick
          }
          double before = 0.0;
          for (int other = 0; other < bricks; ++other)
          {
            const auto c = crossings[other * rays + r];
            before += other != b && c.second - c.first > 0.0 && c.second <= mine.first + 1e-9 ? c.second - c.first : 0.0;
          }
          const double expected = std::exp(-sigma * before);
          EXPECT_NEAR(scanned[static_cast<size_t>(b)][r], expected, 1e-5)
            << bricks << " bricks, brick " << b << ", ray " << r << (positional ? " positional" : "");
          EXPECT_NEAR(gathered[r], expected, 1e-5) << bricks << " bricks, brick " << b << ", ray " << r;
          ++checked;
        }
      }
      EXPECT_GE(checked, rays); // every ray lights some brick
    }
  }
  EXPECT_EQ(ScanRounds(1), 0);
  EXPECT_EQ(ScanRounds(2), 1);
  EXPECT_EQ(ScanRounds(8), 3);
  EXPECT_EQ(ScanRounds(1024), 10);
}

TEST(Bricks, OverlappingOrParallelBricksHaveNoLightOrder)
{
  const BrickBox ghost{ { 0.0, 0.0, -1.0 }, { 1.0, 1.0, 0.1 } };
  EXPECT_TRUE(LightOrder({ ghost, Above }, Directional({ 0.0, 0.0, -1.0 }), 1e-6).empty());
  // Side by side under a light straight down: no ray crosses both, and no order is given
  // (the bricks gather, which leaves them out of each other's product).
  const BrickBox west{ { -1.0, 0.0, 0.0 }, { 0.0, 1.0, 1.0 } };
  EXPECT_TRUE(LightOrder({ west, Above }, Directional({ 0.0, 0.0, -1.0 }), 1e-6).empty());
  EXPECT_EQ(LightOrder({ west, Above }, Directional({ 0.3, 0.0, -1.0 }), 1e-6), (std::vector<int>{ 0, 1 }));
  // Sharing a face within the tolerance, an empty brick last.
  const std::vector<int> order = LightOrder({ Below, BrickBox{}, Above }, Directional({ 0.0, 0.0, -1.0 }), 1e-6);
  EXPECT_EQ(order, (std::vector<int>{ 2, 0, 1 }));
}
