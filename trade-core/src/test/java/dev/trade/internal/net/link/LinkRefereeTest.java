package dev.trade.internal.net.link;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.util.UUID;
import org.junit.jupiter.api.Test;

/** When a lost link's loss is held for its replacement, and when it is taken after all. */
class LinkRefereeTest {
  private static final long HOLD = 1_000_000_000L;
  private final UUID peer = UUID.randomUUID();
  private final LinkReferee swaps = new LinkReferee(HOLD, HOLD, (task, delay) -> {
    throw new AssertionError("nothing is retired here");
  });

  @Test
  void aLossWithoutAHandshakeUnderWayIsTakenAtOnce() throws Exception {
    try (LoopbackLinks links = new LoopbackLinks()) {
      swaps.begun(UUID.randomUUID()); // with another container
      assertFalse(swaps.hold(links.link(peer, "p", new InputStream[1]), "gone", 0));
    }
  }

  @Test
  void aHeldLossIsDroppedWhenAnotherLinkTookItsPlace() throws Exception {
    try (LoopbackLinks links = new LoopbackLinks()) {
      Link old = held(links);
      Link replacement = links.link(peer, "p", new InputStream[1]);
      assertNull(swaps.settle(peer, old, 1), "the handshake is still under way");
      swaps.ended(peer);
      assertNull(swaps.settle(peer, replacement, 2));
      assertNull(swaps.settle(peer, old, 3), "nothing is held any more");
    }
  }

  @Test
  void aHeldLossIsTakenWhenTheHandshakeEndsWithoutALink() throws Exception {
    try (LoopbackLinks links = new LoopbackLinks()) {
      Link old = held(links);
      swaps.ended(peer);
      LinkReferee.Held h = swaps.settle(peer, old, 1);
      assertSame(old, h.link());
      assertEquals("closed by p", h.reason());
    }
  }

  @Test
  void theLossOfTheLinkThatReplacedAHeldOneIsHeldAndTakenInItsPlace() throws Exception {
    try (LoopbackLinks links = new LoopbackLinks()) {
      held(links);
      Link replacement = links.link(peer, "p", new InputStream[1]); // registered, then lost too
      assertTrue(swaps.hold(replacement, "closed by p again", 1));
      swaps.ended(peer);
      assertSame(replacement, swaps.settle(peer, replacement, 2).link());
    }
  }

  @Test
  void handshakesThatNeverEndHoldALossNoLongerThanTheHold() throws Exception {
    // The id in a HELLO is not proved before the handshake ends: one who claims it, again and
    // again, must not keep a lost container linked.
    try (LoopbackLinks links = new LoopbackLinks()) {
      Link old = held(links);
      assertNull(swaps.settle(peer, old, HOLD - 1));
      assertSame(old, swaps.settle(peer, old, HOLD).link());
    }
  }

  /** A link to the peer whose loss is held: a handshake with the peer began before it was lost. */
  private Link held(LoopbackLinks links) throws IOException {
    Link old = links.link(peer, "p", new InputStream[1]);
    swaps.begun(peer);
    assertTrue(swaps.hold(old, "closed by p", 0));
    return old;
  }
}
