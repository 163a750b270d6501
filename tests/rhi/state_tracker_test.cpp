// rhi::StateTracker on its own: which barriers it asks for, and when it refuses.
#include "rhi/error.h"
#include "rhi/state_tracker.h"

#include <gtest/gtest.h>

namespace lumina::rhi {
namespace {

class FakeResource : public IResource {
public:
    explicit FakeResource(std::string name) : name_(std::move(name)) {}
    const std::string& debugName() const override { return name_; }

private:
    std::string name_;
};

using S = ResourceState;

void expectBarrier(const Barrier& barrier, const IResource& resource, S before, S after) {
    EXPECT_EQ(barrier.resource, &resource);
    EXPECT_EQ(barrier.before, before);
    EXPECT_EQ(barrier.after, after);
}

TEST(StateTracker, FirstUseTransitionsFromTheTrackedState) {
    StateTracker tracker;
    FakeResource buffer("buffer");
    tracker.require(buffer, S::CopyDest);
    ASSERT_TRUE(tracker.hasPendingBarriers());
    const auto barriers = tracker.takeBarriers();
    ASSERT_EQ(barriers.size(), 1u);
    expectBarrier(barriers[0], buffer, S::Undefined, S::CopyDest);
    EXPECT_FALSE(barriers[0].isSameState());
    EXPECT_EQ(buffer.trackedState, S::CopyDest);
    EXPECT_FALSE(tracker.hasPendingBarriers());
}

TEST(StateTracker, ReadsInTheSameStateNeedNoBarrier) {
    StateTracker tracker;
    FakeResource texture("texture");
    texture.trackedState = S::ShaderResource;
    for (int command = 0; command < 3; ++command) {
        tracker.require(texture, S::ShaderResource);
        EXPECT_TRUE(tracker.takeBarriers().empty());
        tracker.commandRecorded();
    }
}

TEST(StateTracker, WriteAfterWriteInTheSameStateGetsASameStateBarrier) {
    for (const S state : {S::UnorderedAccess, S::CopyDest}) {
        SCOPED_TRACE(std::string(resourceStateName(state)));
        StateTracker tracker;
        FakeResource buffer("buffer");
        tracker.require(buffer, state);
        EXPECT_EQ(tracker.takeBarriers().size(), 1u);
        tracker.commandRecorded();
        tracker.require(buffer, state);
        const auto barriers = tracker.takeBarriers();
        ASSERT_EQ(barriers.size(), 1u);
        expectBarrier(barriers[0], buffer, state, state);
        EXPECT_TRUE(barriers[0].isSameState());
        tracker.commandRecorded();
    }
}

TEST(StateTracker, UnwrittenUavNeedsNoSameStateBarrier) {
    StateTracker tracker;
    FakeResource buffer("buffer");
    buffer.trackedState = S::UnorderedAccess;
    tracker.require(buffer, S::UnorderedAccess);
    EXPECT_TRUE(tracker.takeBarriers().empty()); // nothing written by this tracker yet
}

TEST(StateTracker, TransitionAfterAWriteClearsTheWrittenMark) {
    StateTracker tracker;
    FakeResource buffer("buffer");
    tracker.require(buffer, S::UnorderedAccess);
    tracker.takeBarriers();
    tracker.commandRecorded();
    tracker.require(buffer, S::ShaderResource);
    auto barriers = tracker.takeBarriers();
    ASSERT_EQ(barriers.size(), 1u);
    expectBarrier(barriers[0], buffer, S::UnorderedAccess, S::ShaderResource);
    tracker.commandRecorded();
    tracker.require(buffer, S::UnorderedAccess);
    barriers = tracker.takeBarriers();
    ASSERT_EQ(barriers.size(), 1u);
    expectBarrier(barriers[0], buffer, S::ShaderResource, S::UnorderedAccess);
    tracker.commandRecorded();
}

TEST(StateTracker, ReadOnlyStatesAreNeverMarkedWritten) {
    StateTracker tracker;
    FakeResource buffer("buffer");
    tracker.require(buffer, S::CopySource);
    tracker.takeBarriers();
    tracker.commandRecorded();
    tracker.require(buffer, S::CopySource);
    EXPECT_TRUE(tracker.takeBarriers().empty());
}

TEST(StateTracker, OneResourceInTwoStatesOfOneCommandThrowsNamingIt) {
    StateTracker tracker;
    FakeResource buffer("shared buffer");
    tracker.require(buffer, S::ShaderResource);
    try {
        tracker.require(buffer, S::UnorderedAccess);
        FAIL() << "SRV + UAV of one resource in one command did not throw";
    } catch (const Error& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("shared buffer"), std::string::npos) << message;
        EXPECT_NE(message.find("ShaderResource"), std::string::npos) << message;
        EXPECT_NE(message.find("UnorderedAccess"), std::string::npos) << message;
    }
}

TEST(StateTracker, OneResourceTwiceInTheSameStateIsFine) {
    StateTracker tracker;
    FakeResource buffer("buffer");
    tracker.require(buffer, S::ShaderResource);
    EXPECT_NO_THROW(tracker.require(buffer, S::ShaderResource));
    EXPECT_EQ(tracker.takeBarriers().size(), 1u);
}

TEST(StateTracker, BarriersComeInRequestOrder) {
    StateTracker tracker;
    FakeResource a("a"), b("b"), c("c");
    tracker.require(b, S::CopySource);
    tracker.require(a, S::CopyDest);
    tracker.require(c, S::RenderTarget);
    const auto barriers = tracker.takeBarriers();
    ASSERT_EQ(barriers.size(), 3u);
    EXPECT_EQ(barriers[0].resource, &b);
    EXPECT_EQ(barriers[1].resource, &a);
    EXPECT_EQ(barriers[2].resource, &c);
}

TEST(StateTracker, ExplicitTransitionsAndSameStateBarriers) {
    StateTracker tracker;
    FakeResource texture("texture");
    tracker.transition(texture, S::RenderTarget);
    tracker.sameStateBarrier(texture);
    const auto barriers = tracker.takeBarriers();
    ASSERT_EQ(barriers.size(), 2u);
    expectBarrier(barriers[0], texture, S::Undefined, S::RenderTarget);
    expectBarrier(barriers[1], texture, S::RenderTarget, S::RenderTarget);
}

TEST(StateTracker, ResetForgetsPendingBarriersAndWrites) {
    StateTracker tracker;
    FakeResource buffer("buffer");
    tracker.require(buffer, S::UnorderedAccess);
    tracker.commandRecorded();
    tracker.reset();
    EXPECT_FALSE(tracker.hasPendingBarriers());
    tracker.require(buffer, S::UnorderedAccess); // tracked state survives, the write mark does not
    EXPECT_TRUE(tracker.takeBarriers().empty());
}

} // namespace
} // namespace lumina::rhi
