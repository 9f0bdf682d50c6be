package dev.trade.internal.codec;

import dev.trade.TRADESerializationException;
import dev.trade.internal.registry.ServiceDescriptor;
import java.lang.annotation.Annotation;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * Encodes a {@code TRADEServiceInfo} as its {@link ServiceDescriptor} and binds decoded descriptors
 * through the codec's {@link InfoBinding}.
 *
 * <p>Each annotation (of the method, and of each parameter) travels in an entry prefixed with its byte length, so that a receiver that does
 * not know or allow an annotation's class (or a class in its members) skips just that annotation,
 * as the descriptor's contract says ("those whose class is known here"). Likewise the sender leaves
 * out annotations whose members it cannot encode.
 */
final class DescriptorCodec {
  private DescriptorCodec() {}

  static void write(Encoder e, ServiceDescriptor d) throws TRADESerializationException {
    ByteSink out = e.out;
    out.writeByte(Tags.SERVICE_INFO);
    out.writeText(d.containerId());
    out.writeText(d.containerName());
    out.writeText(d.host());
    out.writeLong(d.serviceId());
    out.writeText(d.name());
    out.writeVarUInt(d.parameterNames().size());
    for (String s : d.parameterNames()) {
      out.writeText(s);
    }
    for (String s : d.parameterTypeNames()) {
      out.writeText(s);
    }
    out.writeText(d.returnTypeName());
    out.writeVarUInt(d.groups().size());
    for (String s : d.groups()) {
      out.writeText(s);
    }
    writeAnnotations(e, d.annotations());
    out.writeText(d.genericReturnTypeName());
    out.writeVarUInt(d.exceptionTypeNames().size());
    for (String s : d.exceptionTypeNames()) {
      out.writeText(s);
    }
    for (List<Annotation> list : d.parameterAnnotations()) {
      writeAnnotations(e, list);
    }
    e.checkRoom(0);
  }

  /** A count and that many length-prefixed annotation entries, leaving out unencodable ones. */
  private static void writeAnnotations(Encoder e, List<Annotation> annotations)
      throws TRADESerializationException {
    ByteSink entries = new ByteSink(annotations.isEmpty() ? 0 : 64);
    int count = 0;
    for (Annotation a : annotations) {
      int at = entries.size();
      entries.writeInt(0);
      try {
        AnnotationCodec.write(new Encoder(entries, e.limits, e.info), a);
        entries.putInt(at, entries.size() - at - 4);
        count++;
      } catch (TRADESerializationException ex) {
        entries.truncate(at); // leave this annotation out
      }
    }
    e.out.writeVarUInt(count);
    e.out.writeBytes(entries.array(), 0, entries.size());
  }

  static Object read(Decoder d) throws TRADESerializationException {
    d.enter();
    String containerId = d.readText();
    String containerName = d.readText();
    String host = d.readText();
    long serviceId = d.in.readLong();
    String name = d.readText();
    int n = d.readCount(2);
    List<String> parameterNames = readTexts(d, n);
    List<String> parameterTypeNames = readTexts(d, n);
    String returnTypeName = d.readText();
    Set<String> groups = new LinkedHashSet<>(readTexts(d, d.readCount(1)));
    List<Annotation> annotations = readAnnotations(d);
    String genericReturnTypeName = d.readText();
    List<String> exceptionTypeNames = readTexts(d, d.readCount(1));
    List<List<Annotation>> parameterAnnotations = new ArrayList<>(n);
    for (int i = 0; i < n; i++) {
      parameterAnnotations.add(readAnnotations(d));
    }
    d.leave();
    ServiceDescriptor descriptor;
    try {
      descriptor = new ServiceDescriptor(containerId, containerName, host, serviceId, name,
          parameterNames, parameterTypeNames, returnTypeName, groups, annotations,
          genericReturnTypeName, exceptionTypeNames, parameterAnnotations);
    } catch (RuntimeException e) {
      throw new MalformedValueException("invalid service descriptor: " + e.getMessage(), e);
    }
    try {
      return d.info.bind(descriptor);
    } catch (RuntimeException e) {
      throw new TRADESerializationException(
          "Cannot bind the service info of " + descriptor.signature() + ": " + e, e);
    }
  }

  private static List<String> readTexts(Decoder d, int n) throws MalformedValueException {
    List<String> texts = new ArrayList<>(n);
    for (int i = 0; i < n; i++) {
      texts.add(d.readText());
    }
    return texts;
  }

  /** A count and that many annotation entries; those whose class is unknown or refused are skipped. */
  private static List<Annotation> readAnnotations(Decoder d) throws TRADESerializationException {
    int a = d.readCount(5);
    List<Annotation> annotations = new ArrayList<>();
    for (int i = 0; i < a; i++) {
      Annotation annotation = readAnnotationEntry(d);
      if (annotation != null) {
        annotations.add(annotation);
      }
    }
    return annotations;
  }

  /**
   * One length-prefixed annotation, or null if its class (or one in its members) is unknown or
   * refused here; a skipped entry must still be well-formed ({@link AnnotationShape}).
   */
  private static Annotation readAnnotationEntry(Decoder d) throws TRADESerializationException {
    ByteSource in = d.in;
    int length = in.readInt();
    if (length < 1 || length > in.remaining()) {
      throw new MalformedValueException(
          "annotation entry length " + length + " at offset " + in.at(-4) + ", "
              + in.remaining() + " bytes left");
    }
    int start = in.pos;
    int end = start + length;
    int savedLimit = in.limit;
    int savedDepth = d.depth();
    long savedPending = d.suspendPending();
    in.limit = end;
    try {
      // Every entry is checked whole first, so that one is well-formed whether it is decoded
      // here or skipped (where a failed read stops at the class it could not take).
      AnnotationShape.check(d);
      if (in.pos != end) {
        throw new MalformedValueException(
            "annotation entry has " + (end - in.pos) + " bytes after its value");
      }
      in.pos = start;
      d.resetDepth(savedDepth);
      return (Annotation) d.readValue();
    } catch (MalformedValueException e) {
      throw e;
    } catch (TRADESerializationException e) {
      return null; // not known or not allowed here: skip it, as the descriptor's contract says
    } finally {
      in.limit = savedLimit;
      in.pos = end;
      d.resetDepth(savedDepth);
      d.resumePending(savedPending);
    }
  }
}
