package dev.trade.internal.registry;

import java.lang.reflect.Field;
import java.lang.reflect.GenericArrayType;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.lang.reflect.ParameterizedType;
import java.lang.reflect.RecordComponent;
import java.lang.reflect.Type;
import java.lang.reflect.TypeVariable;
import java.lang.reflect.WildcardType;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Deque;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The classes a service's signature declares, which its calls and replies may carry without
 * {@code SERIALIZATIONALLOWLIST}: its parameter, return and exception types, the type arguments
 * of those ({@code Set<Symbol>} declares {@code Symbol}, {@code T extends Term} declares
 * {@code Term}), and, transitively, the superclasses and the declared types of the non-static,
 * non-transient fields (record components) of each class found. Classes of the JDK
 * ({@code java.*}, {@code javax.*}, {@code jdk.*}, {@code sun.*}, {@code com.sun.*}) are included
 * but not looked into: their insides are not the service's declaration.
 *
 * <p>Only code present in this JVM is read: a name that arrives from a peer counts only for a class
 * this JVM has, and what that class declares is read from its local definition. At most
 * {@value #MAX_TYPES} classes per service; the walk stops there. Stateless and thread-safe.
 */
public final class DeclaredTypes {
  /** Bounds the walk through large object graphs; a signature rarely reaches a few dozen. */
  static final int MAX_TYPES = 512;

  /** A binary name inside a {@code Type#getTypeName()} such as {@code java.util.Map<K, a.B[]>}. */
  private static final Pattern NAME = Pattern.compile("[\\p{javaJavaIdentifierStart}][\\p{javaJavaIdentifierPart}.]*");

  private DeclaredTypes() {}

  /** The binary names of the classes {@code method}'s signature declares (see the class comment). */
  public static Set<String> of(Method method) {
    List<Type> roots = new ArrayList<>(List.of(method.getGenericParameterTypes()));
    roots.add(method.getGenericReturnType());
    roots.addAll(List.of(method.getExceptionTypes()));
    return closure(roots);
  }

  /**
   * The binary names of the classes declared by a remote service's return type (its
   * {@link java.lang.reflect.Type#getTypeName()}, with type arguments) and exception types, as far as
   * {@code loader} knows those classes; names it does not know are left out.
   */
  public static Set<String> of(String genericReturnTypeName, List<String> exceptionTypeNames,
      ClassLoader loader) {
    List<Type> roots = new ArrayList<>();
    Matcher m = NAME.matcher(genericReturnTypeName);
    while (m.find()) {
      String token = m.group();
      if (!token.equals("extends") && !token.equals("super")) {
        Class<?> c = Types.resolve(token, loader); // a type variable's name resolves to nothing
        if (c != null) {
          roots.add(c);
        }
      }
    }
    for (String name : exceptionTypeNames) {
      Class<?> c = Types.resolve(name, loader);
      if (c != null) {
        roots.add(c);
      }
    }
    return closure(roots);
  }

  private static Set<String> closure(List<Type> roots) {
    Set<String> names = new LinkedHashSet<>();
    Set<Type> seen = new LinkedHashSet<>();
    Deque<Type> queue = new ArrayDeque<>(roots);
    while (!queue.isEmpty() && names.size() < MAX_TYPES) {
      Type t = queue.poll();
      if (!seen.add(t)) {
        continue;
      }
      if (t instanceof Class<?> c) {
        while (c.isArray()) {
          c = c.getComponentType();
        }
        if (c.isPrimitive() || !names.add(c.getName()) || isJdk(c)) {
          continue;
        }
        members(c, queue);
      } else if (t instanceof ParameterizedType p) {
        queue.add(p.getRawType());
        queue.addAll(List.of(p.getActualTypeArguments()));
      } else if (t instanceof WildcardType w) {
        queue.addAll(List.of(w.getUpperBounds()));
        queue.addAll(List.of(w.getLowerBounds()));
      } else if (t instanceof TypeVariable<?> v) {
        queue.addAll(List.of(v.getBounds()));
      } else if (t instanceof GenericArrayType a) {
        queue.add(a.getGenericComponentType());
      }
    }
    return Collections.unmodifiableSet(names);
  }

  /** Queues the superclass and the declared field (or record component) types of {@code c}. */
  private static void members(Class<?> c, Deque<Type> queue) {
    try {
      if (c.isRecord()) {
        for (RecordComponent rc : c.getRecordComponents()) {
          queue.add(rc.getGenericType());
        }
        return;
      }
      for (Field f : c.getDeclaredFields()) {
        int mod = f.getModifiers();
        if (!Modifier.isStatic(mod) && !Modifier.isTransient(mod) && !f.isSynthetic()) {
          queue.add(f.getGenericType());
        }
      }
      Type superclass = c.getGenericSuperclass();
      if (superclass != null && superclass != Object.class) {
        queue.add(superclass);
      }
    } catch (LinkageError | SecurityException | java.lang.reflect.MalformedParameterizedTypeException
        | TypeNotPresentException e) {
      // A declared type is missing here: what could be read is kept; values of the missing type
      // could not be decoded here anyway.
    }
  }

  private static boolean isJdk(Class<?> c) {
    String n = c.getName();
    return n.startsWith("java.") || n.startsWith("javax.") || n.startsWith("jdk.")
        || n.startsWith("sun.") || n.startsWith("com.sun.");
  }
}
