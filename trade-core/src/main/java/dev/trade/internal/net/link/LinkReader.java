package dev.trade.internal.net.link;

import java.io.IOException;
import java.util.concurrent.CompletableFuture;

/**
 * A link's reading. One thread reads at a time and hands each frame to the link's
 * {@link LinkHandler}: the link's own thread, a worker the {@link ReadWatch} handed reading to
 * (a call served on the reading thread took longer than a tick), or a lone caller waiting for its
 * reply, to whom the link's thread lends reading ({@link #readFor}, {@link ReadRole}). Frames the
 * reading thread sends while the next frame is already buffered (replies to a burst of calls) wait
 * until it has served that burst, and then leave with one system call.
 *
 * <p>Safe for concurrent use: who reads is decided by {@link ReadRole} and the hand-offs.
 */
final class LinkReader {
  /**
   * What the read steps answer when reading went on in another thread; compared by identity, so
   * that no reason why a link ends can be taken for it.
   */
  @SuppressWarnings("StringOperationCanBeSimplified")
  private static final String MOVED = new String("reading moved");

  private final Link link;
  private final LinkInput input;

  LinkReader(Link link, LinkInput input) {
    this.link = link;
    this.input = input;
  }

  /** Reads the link on this thread, after handing out {@code first} if there is one. */
  void loop(LinkInput.Frame first) {
    Thread self = Thread.currentThread();
    String ownName = self.getName();
    // Whichever thread reads the link carries its name, so thread dumps show who reads what.
    self.setName("trade-link-" + link.peerName);
    try {
      readFrames(first);
    } finally {
      self.setName(ownName);
    }
  }

  private void readFrames(LinkInput.Frame first) {
    link.role.takenOver(); // a hand-off's new thread reads now, whoever read before
    String why = first == null ? null : handOut(first);
    while (why == null) {
      if (input.buffered() == 0 && link.role.shouldLend() && !link.socketClosed()) {
        // A lone caller waits for its reply over this link, or may call again soon: it reads
        // the reply itself.
        if (!link.endBurst() || !link.role.lend()) {
          return; // another thread reads now, or reading ended
        }
        continue;
      }
      why = readOne(false);
    }
    if (why != MOVED) {
      end(why);
    }
  }

  /**
   * Waits for {@code reply} until {@code until} ({@link System#nanoTime}), reading the link
   * itself whenever it is lent to callers (see {@link ReadRole}): then the reply wakes no thread
   * on its way to this one. The caller has called {@link ReadRole#borrow} before sending its
   * call, and calls {@link ReadRole#giveBack} after this.
   */
  void readFor(CompletableFuture<?> reply, long until) {
    // A closed link brings no reply; the caller is failed from elsewhere (see LinkHandler#closed).
    while (!reply.isDone() && !link.socketClosed() && System.nanoTime() - until < 0) {
      if (link.role.tryTake()) {
        readLent(reply, until, false);
      } else {
        Thread.onSpinWait();
      }
    }
  }

  /**
   * After {@link #readFor}: waits for {@code reply} in reads that block, until {@code until}
   * ({@link System#nanoTime}), if reading is lent to callers and nobody reads: then the reply wakes
   * this thread directly, as a raw socket's caller is woken, instead of waking the link's thread,
   * which would wake this one in turn. Returns at once otherwise.
   */
  void blockFor(CompletableFuture<?> reply, long until) {
    if (!reply.isDone() && !link.socketClosed() && link.role.tryTake()) {
      readLent(reply, until, true);
    }
  }

  /**
   * A caller that took reading reads the link until its reply is done (and the frames read with it
   * are handed out) or its time is up, then gives reading back, or ends the link. It hands out only
   * frames that arrived whole, and reads either without blocking ({@code block} false: it spins
   * meanwhile) or in reads timed out by {@code until}, so that it stops in time whatever the peer
   * sends; the end of the stream, or a frame larger than the buffer, is left to the link's thread.
   */
  private void readLent(CompletableFuture<?> reply, long until, boolean block) {
    String why = readLentFrames(reply, until, block);
    if (why == null) {
      link.role.release();
    } else if (why != MOVED) {
      end(why);
    }
  }

  /** The reading of {@link #readLent}; answers as {@link #readOne} does. */
  private String readLentFrames(CompletableFuture<?> reply, long until, boolean block) {
    try {
      while (!link.socketClosed()) {
        if (block ? input.holdsWholeFrame() : input.fillWithoutBlocking()) {
          String why = readOne(true);
          if (why != null) {
            return why;
          }
        } else if (!link.endBurst()) { // what was sent while a burst was handed out leaves now
          return MOVED; // the flush blocked and reading went on in another thread
        } else if (reply.isDone() || System.nanoTime() - until >= 0
            || block && !input.fillWithin(until - System.nanoTime())) {
          return null; // done, out of time, or left to the link's thread (see fillWithin)
        } else if (!block) {
          Thread.onSpinWait();
        }
      }
      return "closed";
    } catch (IOException e) {
      return lost(e);
    }
  }

  /**
   * Reads one frame and hands it out; returns null to go on reading, {@link #MOVED} if reading went
   * on in another thread, else why the link ends. A caller that reads ({@code lent}) hands a call,
   * and the reading with it, to another thread: its caller must not wait for it to be served.
   */
  private String readOne(boolean lent) {
    LinkInput.Frame f;
    try {
      if (link.socketClosed()) {
        return "closed";
      }
      if (!input.holdsWholeFrame() && !link.endBurst()) {
        return MOVED; // the flush blocked and reading went on in another thread
      }
      f = input.readFrame();
    } catch (LinkInput.Broken e) {
      return e.getMessage();
    } catch (IOException e) {
      return lost(e);
    } catch (RuntimeException e) {
      return malformed(e);
    }
    if (f == null) {
      return null; // a copy, dropped
    }
    link.output.burst(input.holdsWholeFrame()); // more to hand out after this one
    if (lent && f.type() == Wire.CALL) {
      link.role.takenOver();
      return link.readWatch().read(() -> loop(f)) ? MOVED : "container closing";
    }
    return handOut(f);
  }

  /** Hands a frame to the handler; answers as {@link #readOne} does. */
  private String handOut(LinkInput.Frame f) {
    try {
      return link.handler().frame(link, f.type(), f.payload()) ? null : MOVED;
    } catch (IOException e) {
      return lost(e);
    } catch (RuntimeException e) {
      return malformed(e);
    }
  }

  private String lost(IOException e) {
    return "connection to " + link.peerName + " lost: " + e.getMessage();
  }

  private String malformed(RuntimeException e) {
    return "malformed frame from " + link.peerName + ": " + e;
  }

  /** The reading thread's end: closes the link and tells the handler why. */
  private void end(String reason) {
    link.role.ended();
    // Closed while we read (silence, goodbye...): that is why.
    String closedHere = link.closeReason();
    String why = closedHere != null ? closedHere : reason;
    link.close(why);
    link.handler().closed(link, why);
  }
}
