package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertEquals;

import dev.trade.TRADEContainer;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.internal.codec.AllowList;
import dev.trade.internal.codec.ByteSink;
import dev.trade.internal.codec.Codec;
import dev.trade.internal.codec.InfoBinding;
import dev.trade.internal.codec.Limits;
import dev.trade.internal.net.link.Frames;
import dev.trade.internal.net.link.Wire;
import dev.trade.internal.net.mesh.StateFrames;
import dev.trade.internal.net.mesh.Topology;
import dev.trade.testing.Await;
import java.net.InetSocketAddress;
import java.time.Duration;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * An authenticated member that is not on a call's path cannot answer it, whatever request id it
 * guesses: a reply is accepted only over the link its call went out on, and passed on only by a
 * container that passed the call on, back the way the call came. Before, a provider forwarded a
 * REPLY that named it as the source and the consumer as the destination, and the consumer's
 * slow call returned the forged value.
 */
@Timeout(60)
class ForgedReplyTest {
  private static final Duration WAIT = Duration.ofSeconds(20);
  private final Codec codec = new Codec(AllowList.withDefaults(), Limits.DEFAULT, InfoBinding.NONE);
  private TRADEContainer provider;
  private TRADEContainer consumer;
  private RawPeer member;

  /** A service that answers once the test lets it. */
  public static final class Slow {
    final CountDownLatch called = new CountDownLatch(1);
    final CountDownLatch mayAnswer = new CountDownLatch(1);

    @TRADEService
    public String slow() throws InterruptedException {
      called.countDown();
      mayAnswer.await(30, TimeUnit.SECONDS);
      return "real";
    }
  }

  @AfterEach
  void close() throws Exception {
    if (member != null) {
      member.close();
    }
    consumer.close();
    provider.close();
  }

  private static TRADEContainer.Builder accepting(String name) {
    return TRADEContainer.builder().name(name).property("STARTACCEPTINGCONNECTIONS", "true")
        .property("SERVERIPS", "127.0.0.1@0");
  }

  private static RawPeer linkTo(TRADEContainer c) throws Exception {
    String[] a = c.getServerAddresses().get(0).split("@");
    RawPeer p = RawPeer.connect(new InetSocketAddress(a[0], Integer.parseInt(a[1])));
    p.handshake("member");
    p.send(StateFrames.links(new Topology.LinkState(p.id.toString(), 1, Set.of(c.getId()))));
    return p;
  }

  /** REPLY frames claiming to come from {@code from} for {@code to}'s requests 1 to 300. */
  private void forgeReplies(RawPeer via, String from, String to) throws Exception {
    for (long id = 1; id <= 300; id++) {
      ByteSink out = Frames.start(Wire.REPLY, 64);
      Frames.writeRouting(out, UUID.fromString(from), UUID.fromString(to), Wire.MAX_HOPS);
      out.writeLong(id);
      out.writeByte(Wire.OK);
      codec.write("forged", out);
      via.send(Frames.finish(out));
    }
  }

  /** Starts the consumer's call of slow() and waits until the provider runs it. */
  private CompletableFuture<String> slowCall(Slow slow) throws Exception {
    TRADEServiceConstraints name = new TRADEServiceConstraints().name("slow");
    Await.until(WAIT, () -> !consumer.getAvailableServices(name).isEmpty(), "slow() on the consumer");
    TRADEServiceInfo s = consumer.getAvailableService(name);
    CompletableFuture<String> result = CompletableFuture.supplyAsync(() -> {
      try {
        return s.call(String.class);
      } catch (Exception e) {
        throw new IllegalStateException(e);
      }
    });
    slow.called.await(20, TimeUnit.SECONDS);
    return result;
  }

  @Test
  void aReplyForgedToTheProviderIsNotPassedOn() throws Exception {
    provider = accepting("provider").build();
    Slow slow = new Slow();
    provider.registerAllServices(slow);
    consumer = TRADEContainer.builder().name("consumer")
        .property("CONNECTCONTAINERS", provider.getServerAddresses().get(0)).build();
    member = linkTo(provider);
    CompletableFuture<String> result = slowCall(slow);
    forgeReplies(member, provider.getId(), consumer.getId());
    slow.mayAnswer.countDown();
    assertEquals("real", result.get(20, TimeUnit.SECONDS));
  }

  @Test
  void aReplyForgedStraightToTheConsumerIsNotAccepted() throws Exception {
    provider = accepting("provider").build();
    Slow slow = new Slow();
    provider.registerAllServices(slow);
    consumer = accepting("consumer")
        .property("CONNECTCONTAINERS", provider.getServerAddresses().get(0)).build();
    member = linkTo(consumer);
    CompletableFuture<String> result = slowCall(slow);
    forgeReplies(member, provider.getId(), consumer.getId());
    slow.mayAnswer.countDown();
    assertEquals("real", result.get(20, TimeUnit.SECONDS));
  }
}
