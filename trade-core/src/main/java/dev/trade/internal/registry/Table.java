package dev.trade.internal.registry;

import java.util.List;

/** A container's table of services at a version, as replicated between containers. Immutable. */
public record Table(String containerId, long version, List<ServiceDescriptor> services) {
  public Table {
    services = List.copyOf(services);
  }
}
