// BatchPipe: order, bounded buffers and errors in both directions, with real threads.
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

#include <gtest/gtest.h>

#include "apps/common/batch_pipe.hpp"

namespace navfuse::apps {
namespace {

TEST(BatchPipe, EveryItemArrivesOnceInOrder) {
  BatchPipe<int> pipe(7, 3);  // odd batch size: the last batch is partial
  constexpr int kItems = 100'000;
  std::thread producer([&] {
    for (int i = 0; i < kItems; ++i) {
      pipe.filling().push_back(i);
      pipe.hand_over_if_full();
    }
    pipe.close();
  });
  BatchPipe<int>::Batch batch;
  int expected = 0;
  while (pipe.take(batch)) {
    EXPECT_LE(batch.size(), 7u);
    for (int v : batch) ASSERT_EQ(v, expected++);
  }
  producer.join();
  EXPECT_EQ(expected, kItems);
}

TEST(BatchPipe, ProducerErrorComesAfterTheBatchesBeforeIt) {
  BatchPipe<int> pipe(2, 4);
  pipe.filling() = {1, 2};
  pipe.hand_over();
  pipe.filling().push_back(3);
  pipe.close(std::make_exception_ptr(std::runtime_error("bad frame")));
  BatchPipe<int>::Batch batch;
  ASSERT_TRUE(pipe.take(batch));
  EXPECT_EQ(batch, (std::vector<int>{1, 2}));
  ASSERT_TRUE(pipe.take(batch));
  EXPECT_EQ(batch, (std::vector<int>{3}));
  EXPECT_THROW(pipe.take(batch), std::runtime_error);
}

TEST(BatchPipe, ProducerWaitsWhenEveryBufferIsFullAndLearnsOfTheConsumersFailure) {
  BatchPipe<int> pipe(1, 2);  // one buffer queued, one filling: the second hand-over must wait
  std::atomic<int> handed{0};
  std::thread producer([&] {
    try {
      for (int i = 0;; ++i) {
        pipe.filling().push_back(i);
        pipe.hand_over();
        ++handed;
      }
    } catch (const std::logic_error&) {
    }
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_EQ(handed.load(), 1) << "one free buffer, then the producer waits for the consumer";
  pipe.fail(std::make_exception_ptr(std::logic_error("writer failed")));
  producer.join();  // the waiting hand_over() rethrew the consumer's error
  EXPECT_EQ(handed.load(), 1);
}

}  // namespace
}  // namespace navfuse::apps
