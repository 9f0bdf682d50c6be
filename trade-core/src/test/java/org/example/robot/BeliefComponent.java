package org.example.robot;

import dev.trade.TRADEException;
import dev.trade.TRADEServiceInfo;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/** Implements the interface with @Override only, and is package-private on purpose. */
class BeliefComponent implements BeliefInterface {
  final Set<TRADEServiceInfo> callbacks = new HashSet<>();

  @Override
  public List<Term> queryBelief(Term query) {
    List<Term> result = new ArrayList<>();
    result.add(query);
    return result;
  }

  @Override
  public boolean joinOnGoal(long goalId) {
    return goalId == 42L;
  }

  @Override
  public String getKBName() {
    return "beliefs";
  }

  @Override
  public void registerForNotification(Term term, TRADEServiceInfo callback) {
    callbacks.add(callback);
  }

  @Override
  public int countAll(Object[] items) {
    return items.length;
  }

  void notifyAll(Term term) throws TRADEException {
    for (TRADEServiceInfo cb : callbacks) {
      cb.call(void.class, term);
    }
  }
}
