#include "Core/Parallel.h"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <thread>
#include <vector>

namespace deepshadow
{

int DefaultThreadCount()
{
  if (const char* requested = std::getenv("DEEPSHADOW_THREADS"))
  {
    const int n = std::atoi(requested);
    if (n > 0)
    {
      return n;
    }
  }
  return std::max(1u, std::thread::hardware_concurrency());
}

void ParallelFor(int count, const std::function<void(int)>& body, int threads)
{
  threads = std::min(threads > 0 ? threads : DefaultThreadCount(), std::max(count, 1));
  if (threads <= 1)
  {
    for (int i = 0; i < count; ++i)
    {
      body(i);
    }
    return;
  }
  std::atomic<int> next{ 0 };
  auto worker = [&]() {
    for (int i = next++; i < count; i = next++)
    {
      body(i);
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(threads - 1);
  for (int t = 1; t < threads; ++t)
  {
    pool.emplace_back(worker);
  }
  worker();
  for (auto& thread : pool)
  {
    thread.join();
  }
}

}
