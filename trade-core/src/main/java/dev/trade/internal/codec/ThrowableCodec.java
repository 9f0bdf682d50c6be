package dev.trade.internal.codec;

import dev.trade.TRADERemoteException;
import dev.trade.TRADESerializationException;
import java.lang.invoke.MethodHandle;
import java.lang.invoke.MethodHandles;
import java.lang.reflect.Constructor;
import java.lang.reflect.Modifier;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.Set;

/**
 * Encodes exceptions as type name, message, stack trace and cause chain, and rebuilds them: as their
 * own class when it is allowed, loadable and has a {@code (String, Throwable)}, {@code (String)} or
 * {@code ()} constructor, otherwise as a {@link TRADERemoteException} carrying the remote type
 * name. Other fields of an exception and suppressed exceptions do not travel.
 */
final class ThrowableCodec {

  /** The constructor used to rebuild a class, or {@link #NONE}; cached per class. */
  private static final ClassValue<Maker> MAKERS =
      new ClassValue<>() {
        @Override
        protected Maker computeValue(Class<?> type) {
          return Maker.find(type);
        }
      };

  private ThrowableCodec() {}

  static void write(Encoder e, Throwable t) throws TRADESerializationException {
    Set<Throwable> seen = Collections.newSetFromMap(new IdentityHashMap<>());
    write(e, t, seen);
  }

  private static void write(Encoder e, Throwable t, Set<Throwable> seen)
      throws TRADESerializationException {
    e.enter(t);
    seen.add(t);
    String typeName = t.getClass().getName();
    String message = t.getMessage();
    if (t.getClass() == TRADERemoteException.class) { // travel on as the original exception
      typeName = ((TRADERemoteException) t).getRemoteTypeName();
      message = ((TRADERemoteException) t).getRemoteMessage();
    }
    ByteSink out = e.out;
    out.writeByte(Tags.THROWABLE);
    out.writeText(typeName);
    out.writeNullableText(message);
    StackTraceElement[] frames = t.getStackTrace();
    int n = Math.min(frames.length, e.limits.maxStackFrames());
    out.writeVarUInt(n);
    for (int i = 0; i < n; i++) {
      StackTraceElement f = frames[i];
      out.writeNullableText(f.getClassLoaderName());
      out.writeNullableText(f.getModuleName());
      out.writeNullableText(f.getModuleVersion());
      out.writeText(f.getClassName());
      out.writeText(f.getMethodName());
      out.writeNullableText(f.getFileName());
      out.writeInt(f.getLineNumber());
    }
    e.checkRoom(0);
    Throwable cause = t.getCause();
    if (cause == null || seen.contains(cause) || seen.size() > Tags.MAX_CAUSES) {
      out.writeByte(Tags.NULL);
    } else {
      write(e, cause, seen);
    }
    e.leave();
  }

  static Throwable read(Decoder d) throws TRADESerializationException {
    d.enter();
    String typeName = d.readName();
    String message = d.readNullableText();
    int n = d.readCount(10); // the smallest frame: three empty texts, two names, a null, an int
    if (n > d.limits.maxStackFrames()) {
      throw new MalformedValueException(
          n + " stack frames exceed the limit of " + d.limits.maxStackFrames());
    }
    StackTraceElement[] frames = new StackTraceElement[n];
    for (int i = 0; i < n; i++) {
      String loaderName = d.readNullableText();
      String moduleName = d.readNullableText();
      String moduleVersion = d.readNullableText();
      String className = d.readName();
      String methodName = d.readName();
      String fileName = d.readNullableText();
      int line = d.in.readInt();
      frames[i] = new StackTraceElement(
          loaderName, moduleName, moduleVersion, className, methodName, fileName, line);
    }
    Object cause = d.readValue();
    if (cause != null && !(cause instanceof Throwable)) {
      throw new MalformedValueException("cause of " + typeName + " is a "
          + cause.getClass().getName() + ", not an exception");
    }
    d.leave();
    Throwable t = rebuild(d, typeName, message, (Throwable) cause);
    t.setStackTrace(frames);
    return t;
  }

  private static Throwable rebuild(Decoder d, String typeName, String message, Throwable cause) {
    if (TypeNames.isValid(typeName) && d.allowList.isAllowed(typeName)) {
      try {
        Class<?> type = Class.forName(typeName, false, d.loader);
        Throwable t = MAKERS.get(type).make(message, cause);
        if (t != null) {
          return t;
        }
      } catch (ClassNotFoundException | LinkageError e) {
        // not known here: fall through to the stand-in
      }
    }
    return new TRADERemoteException(typeName, message, cause);
  }

  /** One way to construct a throwable class, or none. */
  private static final class Maker {
    static final Maker NONE = new Maker(null, -1);
    private final MethodHandle handle; // returns Object
    private final int parameters; // 2: (String, Throwable); 1: (String); 0: ()

    private Maker(MethodHandle handle, int parameters) {
      this.handle = handle;
      this.parameters = parameters;
    }

    static Maker find(Class<?> type) {
      if (!Throwable.class.isAssignableFrom(type) || Modifier.isAbstract(type.getModifiers())) {
        return NONE;
      }
      Class<?>[][] shapes = {{String.class, Throwable.class}, {String.class}, {}};
      for (Class<?>[] shape : shapes) {
        try {
          Constructor<?> c = type.getDeclaredConstructor(shape);
          if (c.trySetAccessible()) {
            MethodHandle h = MethodHandles.lookup().unreflectConstructor(c);
            return new Maker(h.asType(h.type().changeReturnType(Object.class)), shape.length);
          }
        } catch (ReflectiveOperationException | RuntimeException | LinkageError e) {
          // try the next shape
        }
      }
      return NONE;
    }

    /** A new instance, or null if there is no usable constructor or it failed. */
    Throwable make(String message, Throwable cause) {
      if (handle == null) {
        return null;
      }
      Throwable t;
      try {
        switch (parameters) {
          case 2 -> t = (Throwable) (Object) handle.invokeExact(message, cause);
          case 1 -> t = (Throwable) (Object) handle.invokeExact(message);
          default -> t = (Throwable) (Object) handle.invokeExact();
        }
      } catch (Exception | LinkageError e) {
        return null;
      } catch (Error e) {
        throw e;
      } catch (Throwable e) {
        return null;
      }
      if (parameters < 2 && cause != null && t.getCause() == null) {
        try {
          t.initCause(cause);
        } catch (IllegalStateException | IllegalArgumentException e) {
          // the constructor fixed the cause already
        }
      }
      return t;
    }
  }
}
