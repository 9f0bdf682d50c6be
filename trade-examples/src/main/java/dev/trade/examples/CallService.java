package dev.trade.examples;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import java.lang.reflect.Method;
import java.lang.reflect.Type;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * Calls one service of a running TRADE system from the command line, from a container of its own:
 *
 * <pre>
 * java -cp CLASSPATH dev.trade.examples.CallService [--config FILE] [--groups G1,G2] [--wait SECONDS]
 *     [--types CLASS,...] SERVICE [ARGUMENT...]
 * </pre>
 *
 * It waits (default 10 s) until a service named SERVICE, in all of the groups and taking as many
 * parameters as there are arguments, is available, converts each argument to its parameter type
 * (numbers, {@code true}/{@code false}, characters and strings as they are typed; records, arrays,
 * lists and maps as JSON, such as {@code '{"x":0.4,"y":0.1}'} or {@code '[1,2,3]'}), calls it and
 * prints {@code openGripper(int) @ arm returned true}. Arguments are numbered from 0, as the
 * library's own messages number them. Exit status: 0 when the call returned (and for
 * {@code --help}), 1 when it failed or no service came, 2 for bad arguments or configuration.
 *
 * <p>A service info names its parameters' classes without their type arguments ({@code List}, not
 * {@code List<Pose>}), so an object inside a list or map says what it is with {@code "@type"}, or
 * {@code --types} names a class on the class path that declares the method, whose generic
 * signature then says it.
 */
public final class CallService {
  private final Object joined = new Object();

  private CallService() {}

  /** The {@code joined} callback: wakes the waiting main thread. */
  @TRADEService
  public void serviceJoined(TRADEServiceInfo service) {
    synchronized (joined) {
      joined.notifyAll();
    }
  }

  static final String USAGE = """
      usage: CallService [--config FILE] [--groups G1,G2] [--wait SECONDS] [--types C1,C2]
                         SERVICE [ARGUMENT...]
        Calls the service SERVICE, in all of the groups and with as many parameters as arguments.
        --config FILE     the trade.properties of the calling container (default: built-in)
        --groups G1,G2    only services in all of these groups
        --wait SECONDS    how long to wait for the service to appear (default 10)
        --types C1,C2     classes on the class path that declare the service's method: its
                          generic signature (List<Pose>) says what lists and maps hold
        ARGUMENT          as typed for numbers, true/false, characters and strings;
                          JSON for records, arrays, lists and maps: '{"x":0.4,"y":0.1}' '[1,2]'
      Classes of records the service takes must be on the class path (java -cp).
      A service names its parameters' classes without type arguments (List, not List<Pose>):
      without --types, an object in a list or map names its class with "@type":
        '[{"@type":"com.acme.Pose","x":0.4,"y":0.1}]'   ("@type":"java.util.Map" for a map)""";

  public static void main(String[] args) throws InterruptedException {
    if (args.length > 0 && (args[0].equals("--help") || args[0].equals("-h"))) {
      System.out.println(USAGE);
      System.exit(0);
    }
    Path config = null;
    List<String> groups = new ArrayList<>();
    long waitSeconds = 10;
    List<Class<?>> types = new ArrayList<>();
    int i = 0;
    try {
      for (; i < args.length && args[i].startsWith("--"); i += 2) {
        if (i + 1 >= args.length) {
          throw new IllegalArgumentException(args[i] + " needs a value");
        }
        switch (args[i]) {
          case "--config" -> config = Path.of(args[i + 1]);
          case "--groups" -> groups = List.of(args[i + 1].split(","));
          case "--wait" -> waitSeconds = Long.parseLong(args[i + 1]);
          case "--types" -> types = classes(args[i + 1]);
          default -> throw new IllegalArgumentException("unknown option " + args[i]);
        }
      }
      if (i >= args.length) {
        throw new IllegalArgumentException("no service named");
      }
    } catch (IllegalArgumentException e) {
      System.err.println(e.getMessage() + "\n" + USAGE);
      System.exit(2);
    }
    ExampleContainers.configureLogging(false);
    TRADEContainer trade;
    try {
      trade = ExampleContainers.start("call", config);
    } catch (IllegalArgumentException e) {
      System.err.println(e.getMessage());
      System.exit(2);
      return;
    }
    String name = args[i];
    List<String> arguments = List.of(args).subList(i + 1, args.length);
    TRADEServiceConstraints wanted =
        new TRADEServiceConstraints().name(name).inGroups(groups.toArray(new String[0]));
    int status;
    try {
      TRADEServiceInfo service = new CallService().await(trade, wanted, arguments.size(),
          TimeUnit.SECONDS.toNanos(waitSeconds));
      if (service == null) {
        System.out.println("no service " + wanted + " with " + arguments.size()
            + " parameters came within " + waitSeconds + " s");
        status = 1;
      } else {
        Object result = service.call(Object.class, convert(service, arguments, types));
        System.out.println(service.serviceString + " @ " + service.getContainerName()
            + (service.serviceReturnTypeName.equals("void") ? " returned" : " returned " + result));
        status = 0;
      }
    } catch (TRADEException e) {
      System.out.println("failed: " + e.getClass().getSimpleName() + ": " + e.getMessage());
      status = 1;
    } catch (IllegalArgumentException e) {
      System.out.println(e.getMessage());
      status = 2;
    }
    trade.close();
    System.exit(status);
  }

  /** The first service matching {@code wanted} with {@code arity} parameters, or null in time. */
  private TRADEServiceInfo await(TRADEContainer trade, TRADEServiceConstraints wanted, int arity,
      long timeoutNanos) throws TRADEException, InterruptedException {
    long deadline = System.nanoTime() + timeoutNanos;
    // Wakes us when something matching joins; the loop re-checks, so no join is missed.
    trade.requestNotification(this, "joined", wanted, null, "serviceJoined");
    synchronized (joined) {
      while (true) {
        for (TRADEServiceInfo s : trade.getAvailableServices(wanted)) {
          if (s.serviceParameterTypeNames.length == arity) {
            return s;
          }
        }
        long remaining = deadline - System.nanoTime();
        if (remaining <= 0) {
          return null;
        }
        TimeUnit.NANOSECONDS.timedWait(joined, remaining);
      }
    }
  }

  /**
   * The arguments as the service's parameter types, as far as the service info says them.
   *
   * @throws IllegalArgumentException naming the argument that does not fit
   */
  static Object[] convert(TRADEServiceInfo service, List<String> arguments) {
    return convert(service, arguments, List.of());
  }

  /**
   * The arguments as the service's parameter types, generic where one of {@code types} declares
   * the service's method.
   *
   * @throws IllegalArgumentException naming the argument that does not fit
   */
  static Object[] convert(TRADEServiceInfo service, List<String> arguments, List<Class<?>> types) {
    Type[] generic = genericParameterTypes(service, types);
    Object[] values = new Object[arguments.size()];
    for (int i = 0; i < values.length; i++) {
      String type = service.serviceParameterTypeNames[i];
      String text = arguments.get(i);
      try {
        values[i] = switch (type) {
          case "int", "java.lang.Integer" -> Integer.valueOf(text);
          case "long", "java.lang.Long" -> Long.valueOf(text);
          case "short", "java.lang.Short" -> Short.valueOf(text);
          case "byte", "java.lang.Byte" -> Byte.valueOf(text);
          case "double", "java.lang.Double" -> Double.valueOf(text);
          case "float", "java.lang.Float" -> Float.valueOf(text);
          case "boolean", "java.lang.Boolean" -> bool(text);
          case "char", "java.lang.Character" -> character(text);
          case "java.lang.String", "java.lang.Object", "java.lang.CharSequence" -> text;
          default -> Json.to(generic != null ? generic[i] : parameterType(service, i), Json.parse(text));
        };
      } catch (IllegalArgumentException e) {
        throw new IllegalArgumentException("Argument " + i + " ('" + service.serviceParameterNames[i]
            + "', expected " + (generic != null ? generic[i].getTypeName() : type) + ") '" + text
            + "' does not fit: " + e.getMessage() + "\n    for service " + service.serviceString);
      }
    }
    return values;
  }

  /**
   * The generic parameter types of the public method of one of {@code types} that has the
   * service's name and parameter classes, or null when none has.
   */
  private static Type[] genericParameterTypes(TRADEServiceInfo service, List<Class<?>> types) {
    for (Class<?> c : types) {
      for (Method m : c.getMethods()) {
        if (m.getName().equals(service.serviceName) && Arrays.equals(service.serviceParameterTypeNames,
            Arrays.stream(m.getParameterTypes()).map(Class::getTypeName).toArray())) {
          return m.getGenericParameterTypes();
        }
      }
    }
    return null;
  }

  /** The classes {@code --types} names. */
  private static List<Class<?>> classes(String names) {
    List<Class<?>> classes = new ArrayList<>();
    for (String name : names.split(",")) {
      try {
        classes.add(Class.forName(name.trim(), false, CallService.class.getClassLoader()));
      } catch (ClassNotFoundException | LinkageError e) {
        throw new IllegalArgumentException("--types: class " + name.trim()
            + " is not on the class path; add it with java -cp");
      }
    }
    return classes;
  }

  private static Class<?> parameterType(TRADEServiceInfo service, int i) {
    try {
      return service.getServiceParameterTypes()[i];
    } catch (TypeNotPresentException e) {
      throw new IllegalArgumentException("class " + e.typeName() + " is not on the class path;"
          + " add it with java -cp");
    }
  }

  private static Boolean bool(String text) {
    if (!text.equals("true") && !text.equals("false")) {
      throw new IllegalArgumentException("expected true or false");
    }
    return Boolean.valueOf(text);
  }

  private static Character character(String text) {
    if (text.length() != 1) {
      throw new IllegalArgumentException("expected one character");
    }
    return text.charAt(0);
  }
}
