package dev.trade.internal.net.mesh;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.internal.codec.AllowList;
import dev.trade.internal.codec.Codec;
import dev.trade.internal.codec.InfoBinding;
import dev.trade.internal.codec.Limits;
import dev.trade.internal.net.link.Wire;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.registry.Table;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/** What a link's reader drops before it queues a replication frame for the control thread. */
class FloodFilterTest {
  private final Topology topology = new Topology("me", TimeUnit.SECONDS.toNanos(60));
  private final Registry registry = new Registry("me", "me", "host");
  private final TableKeeper tables = new TableKeeper(registry, TimeUnit.SECONDS.toNanos(60));
  private final FloodFilter filter = new FloodFilter(topology, registry, tables);
  private final Codec codec = new Codec(AllowList.withDefaults(), Limits.DEFAULT, InfoBinding.NONE);
  /** Stand-ins for links: the filter compares them by identity. */
  private static final Object A = new Object();
  private static final Object B = new Object();
  private static final Object C = new Object();

  private static byte[] payload(byte[] frame) {
    return Arrays.copyOfRange(frame, Wire.HEADER, frame.length);
  }

  /** Asks the filter about {@code payload} as a link's input buffer holds it: amid other bytes. */
  private boolean stale(Object from, int type, byte[] payload) {
    byte[] buf = new byte[payload.length + 7];
    Arrays.fill(buf, (byte) 0x5a);
    System.arraycopy(payload, 0, buf, 3, payload.length);
    return filter.isStale(from, type, buf, 3, payload.length);
  }

  private static byte[] links(String owner, long version) {
    return payload(StateFrames.links(new Topology.LinkState(owner, version, Set.of("a"))));
  }

  @Test
  void aLinkStateIsQueuedOnceWhateverTheLinksItComesOver() {
    assertFalse(stale(A, Wire.LINKS, links("b", 1)));
    assertTrue(stale(A, Wire.LINKS, links("b", 1)), "queued already, not applied yet");
    assertFalse(stale(A, Wire.LINKS, links("b", 2)), "newer");
    assertTrue(stale(A, Wire.LINKS, links("b", 1)), "older than one queued");
    assertTrue(stale(A, Wire.LINKS, links("me", 9)), "our own");
  }

  @Test
  void linksThatSentAVersionNeedNoCopyOfIt() {
    assertFalse(stale(A, Wire.LINKS, links("b", 1)));
    assertTrue(stale(B, Wire.LINKS, links("b", 1)));
    assertTrue(filter.hasCopy(A, "b", 1));
    assertTrue(filter.hasCopy(B, "b", 1));
    assertFalse(filter.hasCopy(C, "b", 1), "C never sent it");
    assertFalse(filter.hasCopy(A, "x", 1), "another owner");
    assertFalse(stale(C, Wire.LINKS, links("b", 2)));
    assertTrue(filter.hasCopy(C, "b", 1), "a newer version is queued: that one goes out instead");
    assertFalse(filter.hasCopy(A, "b", 2), "A sent only the older one");
    assertTrue(filter.hasCopy(C, "b", 2));
  }

  @Test
  void aClosedLinkIsForgotten() {
    assertFalse(stale(A, Wire.LINKS, links("b", 1)));
    assertTrue(stale(B, Wire.LINKS, links("b", 1)));
    filter.forget(A);
    assertFalse(filter.hasCopy(A, "b", 1), "A is no longer held");
    assertTrue(filter.hasCopy(B, "b", 1), "B is");
  }

  @Test
  void aVersionIsSupersededOnceANewerOneIsQueued() {
    assertFalse(stale(A, Wire.LINKS, links("b", 1)));
    assertFalse(filter.superseded(Wire.LINKS, "b", 1), "the newest queued");
    assertFalse(stale(B, Wire.LINKS, links("b", 2)));
    assertTrue(filter.superseded(Wire.LINKS, "b", 1));
    assertFalse(filter.superseded(Wire.LINKS, "b", 2));
    assertFalse(filter.superseded(Wire.TABLE, "b", 1), "link states and tables are apart");
    assertFalse(filter.superseded(Wire.LINKS, "c", 1), "another owner");
    assertFalse(stale(A, Wire.TABLE, table("b", 3)));
    assertFalse(stale(B, Wire.TABLE, table("b", 4)));
    assertTrue(filter.superseded(Wire.TABLE, "b", 3));
    assertFalse(filter.superseded(Wire.TABLE, "b", 4));
  }

  @Test
  void aPrunedLinkStateMayComeAgain() {
    assertFalse(stale(A, Wire.LINKS, links("b", 1)));
    topology.apply(new Topology.LinkState("b", 1, Set.of("a")));
    assertTrue(stale(A, Wire.LINKS, links("b", 1)));
    topology.pruneUnreachable(0, 1);
    topology.pruneUnreachable(10, 1); // unreachable for longer than the grace: forgotten
    filter.pruned();
    assertFalse(stale(A, Wire.LINKS, links("b", 1)));
  }

  private byte[] table(String owner, long version) {
    return payload(StateFrames.table(codec, new Table(owner, version, List.of())));
  }

  private byte[] delta(String owner, long version) {
    return payload(StateFrames.delta(codec, owner, version, List.of(), List.of()));
  }

  @Test
  void aTableIsQueuedOnceWhateverTheLinksItComesOver() {
    assertFalse(stale(A, Wire.TABLE, table("x", 1)));
    assertTrue(stale(A, Wire.TABLE, table("x", 1)), "queued already, not applied yet");
    assertTrue(stale(A, Wire.DELTA, delta("x", 1)), "a table at its version is queued");
    assertFalse(stale(A, Wire.TABLE, table("x", 2)), "newer");
    registry.applyTables(List.of(new Table("y", 3, List.of())), Map.of("y", 1));
    assertTrue(stale(A, Wire.TABLE, table("y", 3)), "applied already");
    assertFalse(stale(A, Wire.LINKS, new byte[] {1}), "malformed: left to the control thread");
  }

  @Test
  void aDeltaThatPassesLetsTheTableAtItsVersionPass() {
    assertFalse(stale(A, Wire.DELTA, delta("x", 5)));
    // Not following what is known here, the control thread asks for the table at that version.
    assertFalse(stale(A, Wire.TABLE, table("x", 5)), "the table asked for was dropped");
  }

  @Test
  void aTableForgottenHereMayComeAgain() {
    assertFalse(stale(A, Wire.TABLE, table("x", 1)));
    filter.pruned(); // neither listed nor waiting: forgotten
    assertFalse(stale(A, Wire.TABLE, table("x", 1)));
    tables.table(new Table("x", 1, List.of()), null, 0); // waits for a route
    filter.pruned();
    assertTrue(stale(A, Wire.TABLE, table("x", 1)), "waiting for a route: kept");
  }
}
