function [core, due] = core_firing_due(core, ports)
% Whether the firing taken should run now: its inputs are here, or
% --ready-timeout (> 0) has passed since its FIRE.
  due = false;
  if isempty(core.pending) || core.pending_fired
    return;
  end
  [~, lacking] = inputs_of_tick(ports, core.pending.tick);
  core.waiting = ~isempty(lacking);
  if ~core.waiting
    due = true;
  elseif core.ready_timeout_s > 0 && toc(core.pending_since) >= core.ready_timeout_s
    say(core.name, 'firing %d (tick %d): inputs incomplete after %g s; firing anyway (--ready-timeout)', ...
        core.pending.firing_id, core.pending.tick, core.ready_timeout_s);
    due = true;
  end
end
