package org.example.contraband;

import java.io.IOException;
import java.io.ObjectInputStream;
import java.io.Serializable;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * A {@code Serializable} class in a package that no service signature names, so that no
 * container allows it unless SERIALIZATIONALLOWLIST says so. It counts how often Java
 * serialization rebuilt one.
 */
public final class Parcel implements Serializable {
  private static final long serialVersionUID = 1L;
  public static final AtomicInteger DESERIALIZED = new AtomicInteger();

  private final String content;

  public Parcel(String content) {
    this.content = content;
  }

  public String content() {
    return content;
  }

  private void readObject(ObjectInputStream in) throws IOException, ClassNotFoundException {
    in.defaultReadObject();
    DESERIALIZED.incrementAndGet();
  }
}
