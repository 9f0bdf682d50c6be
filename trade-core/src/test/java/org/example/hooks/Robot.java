package org.example.hooks;

import dev.trade.TRADEService;
import java.util.ArrayList;
import java.util.List;

/** Services to wrap: they record their own calls in the same list as the recorder. */
public class Robot {
  final List<String> events;

  public Robot(List<String> events) {
    this.events = events;
  }

  @TRADEService
  public boolean openGripper(int speed, String how) {
    events.add("S openGripper " + speed + " " + how);
    return speed > 2;
  }

  @TRADEService
  public void sayText(String text) {
    events.add("S sayText " + text);
  }

  @TRADEService
  public int fail(int code) {
    events.add("S fail " + code);
    throw new IllegalArgumentException("code " + code);
  }

  @TRADEService
  public List<String> echo(List<String> items) {
    events.add("S echo " + items);
    return new ArrayList<>(items);
  }
}
