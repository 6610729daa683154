#include "quaternia/distribute/in_process_channel.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

namespace quaternia {
namespace {

std::vector<uint8_t> bytesOf(int64_t value) {
    return MessageWriter().put(value).bytes();
}

int64_t valueOf(const Message& message) {
    return MessageReader(message.bytes).get<int64_t>();
}

TEST(MessageBytes, ValuesAndByteStringsReadBackInOrder) {
    struct Pair {
        int32_t a;
        double b;
    };
    const std::vector<uint8_t> blob = {9, 8, 7};
    MessageWriter writer;
    writer.put(int64_t(-5)).putBytes(blob).put(Pair{3, 0.25}).putBytes({});
    MessageReader reader(writer.bytes());
    EXPECT_EQ(reader.get<int64_t>(), -5);
    EXPECT_EQ(reader.getBytes(), blob);
    const Pair pair = reader.get<Pair>();
    EXPECT_EQ(pair.a, 3);
    EXPECT_EQ(pair.b, 0.25);
    EXPECT_TRUE(reader.getBytes().empty());
    EXPECT_THROW(reader.get<int8_t>(), std::runtime_error);  // nothing left
    std::vector<uint8_t> truncated = MessageWriter().putBytes(blob).bytes();
    truncated.pop_back();
    EXPECT_THROW(MessageReader(truncated).getBytes(), std::runtime_error);
}

TEST(InProcessChannel, MessagesArriveInOrderWithTheirSourceAndTag) {
    InProcessNetwork network(3);
    EXPECT_EQ(network.channel(2).rank(), 2);
    EXPECT_EQ(network.channel(2).size(), 3);
    network.channel(1).send(0, MessageTag::Ready, {});
    network.channel(2).send(0, MessageTag::Result, bytesOf(7));
    network.channel(1).send(0, MessageTag::Result, bytesOf(8));
    Channel& zero = network.channel(0);
    auto first = zero.poll(nullptr), second = zero.poll(nullptr), third = zero.poll(nullptr);
    ASSERT_TRUE(first && second && third);
    EXPECT_EQ(first->source, 1);
    EXPECT_EQ(first->tag, MessageTag::Ready);
    EXPECT_EQ(second->source, 2);
    EXPECT_EQ(valueOf(*second), 7);
    EXPECT_EQ(third->source, 1);
    EXPECT_EQ(valueOf(*third), 8);
    EXPECT_FALSE(zero.poll(nullptr));
    EXPECT_THROW(zero.send(3, MessageTag::Assign, {}), std::out_of_range);
}

// A wait takes the first message of its source and tag, and leaves the others where they were.
TEST(InProcessChannel, WaitTakesOnlyItsSourceAndTag) {
    InProcessNetwork network(3);
    Channel& one = network.channel(1);
    network.channel(2).send(1, MessageTag::Assign, bytesOf(1));
    network.channel(0).send(1, MessageTag::Summary, bytesOf(2));
    std::thread later([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        network.channel(0).send(1, MessageTag::Assign, bytesOf(3));
    });
    auto message = one.wait(0, MessageTag::Assign, nullptr);  // sleeps until the thread's
    later.join();
    ASSERT_TRUE(message);
    EXPECT_EQ(valueOf(*message), 3);
    auto left = one.poll(nullptr);
    ASSERT_TRUE(left);
    EXPECT_EQ(left->source, 2);
    ASSERT_TRUE((left = one.poll(nullptr)));
    EXPECT_EQ(left->tag, MessageTag::Summary);
}

TEST(InProcessChannel, WaitEndsWhenCancelled) {
    InProcessNetwork network(2);
    std::atomic<bool> cancel{false};
    std::thread canceller([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        cancel = true;
    });
    const auto start = std::chrono::steady_clock::now();
    EXPECT_FALSE(network.channel(1).wait(0, MessageTag::Assign, &cancel));
    canceller.join();
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
}

// A lost rank's messages sent before it died still arrive, then its Lost; after that it neither
// sends nor hears anything.
TEST(InProcessChannel, LostRankIsReportedAfterItsLastMessages) {
    InProcessNetwork network(3);
    network.channel(2).send(0, MessageTag::Result, bytesOf(5));
    network.channel(0).send(2, MessageTag::Assign, bytesOf(6));
    network.lose(2);
    EXPECT_TRUE(network.isLost(2));
    EXPECT_FALSE(network.isLost(1));
    network.channel(2).send(0, MessageTag::Result, bytesOf(9));  // dropped: it is dead
    network.channel(0).send(2, MessageTag::Assign, bytesOf(10));
    Channel& zero = network.channel(0);
    auto result = zero.poll(nullptr), lost = zero.poll(nullptr);
    ASSERT_TRUE(result && lost);
    EXPECT_EQ(valueOf(*result), 5);
    EXPECT_EQ(lost->source, 2);
    EXPECT_EQ(lost->tag, MessageTag::Lost);
    EXPECT_FALSE(zero.poll(nullptr));
    EXPECT_FALSE(network.channel(2).poll(nullptr));
    EXPECT_FALSE(network.channel(2).wait(0, MessageTag::Assign, nullptr));  // does not block
    network.lose(2);                                                        // once only
    EXPECT_FALSE(zero.poll(nullptr));
}

}  // namespace
}  // namespace quaternia
