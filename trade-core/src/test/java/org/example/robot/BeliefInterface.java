package org.example.robot;

import dev.trade.TRADEService;
import dev.trade.TRADEServiceInfo;
import java.util.List;

/** DIARC's style: annotations on interface methods only, together with the user's own. */
public interface BeliefInterface {
  @TRADEService
  @Action
  List<Term> queryBelief(Term query);

  @TRADEService
  boolean joinOnGoal(long goalId);

  @TRADEService
  String getKBName();

  @TRADEService
  void registerForNotification(Term term, TRADEServiceInfo callback);

  @TRADEService
  int countAll(Object[] items);
}
