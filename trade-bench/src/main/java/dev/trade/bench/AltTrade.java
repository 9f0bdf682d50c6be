package dev.trade.bench;

import java.io.File;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.util.ArrayList;
import java.util.List;

/**
 * The client of {@code trade-alt}: TRADE from another build, loaded in this JVM beside the current
 * one, so that an A/B of a change measures both its calling and its serving side in the same run.
 * Classes of {@code dev.trade} come from {@code -Dbench.altClasspath}, child first; the {@link Rpc}
 * interface is shared with the harness.
 */
final class AltTrade {
  private AltTrade() {}

  static Rpc connect(String address) throws Exception {
    String path = System.getProperty("bench.altClasspath");
    if (path == null) {
      throw new IllegalStateException("trade-alt needs -Dbench.altClasspath=<class path>");
    }
    ClassLoader loader = new ChildFirst(urls(path), AltTrade.class.getClassLoader());
    try {
      Method connect = Class.forName(TradeRpc.class.getName(), true, loader)
          .getDeclaredMethod("connect", String.class);
      connect.setAccessible(true); // package-private, and in another run-time package here
      return (Rpc) connect.invoke(null, address);
    } catch (InvocationTargetException e) {
      throw e.getCause() instanceof Exception ex ? ex : e;
    }
  }

  private static URL[] urls(String path) throws MalformedURLException {
    List<URL> urls = new ArrayList<>();
    for (String entry : path.split(File.pathSeparator)) {
      urls.add(new File(entry).toURI().toURL());
    }
    return urls.toArray(new URL[0]);
  }

  /** Loads TRADE and the harness's TRADE client itself; everything else from its parent. */
  private static final class ChildFirst extends URLClassLoader {
    ChildFirst(URL[] urls, ClassLoader parent) {
      super(urls, parent);
    }

    @Override
    protected Class<?> loadClass(String name, boolean resolve) throws ClassNotFoundException {
      boolean own = name.startsWith("dev.trade.") && !name.startsWith(Rpc.class.getName());
      if (!own) {
        return super.loadClass(name, resolve);
      }
      synchronized (getClassLoadingLock(name)) {
        Class<?> c = findLoadedClass(name);
        if (c == null) {
          c = findClass(name);
        }
        if (resolve) {
          resolveClass(c);
        }
        return c;
      }
    }
  }
}
