; hecker_loop_asm: the inner loop of Hecker's part V listing 2; twin of hecker_loop in
; kernel/mappers/hecker.cpp. One pointer holds both texel coordinates; the v fraction's carry picks
; one of two step-table entries through sbb, the u fraction's carry is added by adc.
;   esi: texel pointer   edi: destination   ecx: u fraction (bits 31..16)   edx: v fraction
;   ebx: u fraction step   ebp: 0 or -1 (v carried)   al: texel
;   [esp]: step table, v carried   [esp+4]: v did not carry   [esp+8]: v fraction step   [esp+12]: count

bits 32

%include "hecker.inc"
%include "loop.inc"

section .text

global hecker_loop_asm
hecker_loop_asm:
    LOOP_ENTER 0
    mov eax, LOOP_ARG(0)
    sub esp, 16
    mov ecx, [eax + HECKER_step_carry]
    mov [esp], ecx
    mov ecx, [eax + HECKER_step_no_carry]
    mov [esp + 4], ecx
    mov ecx, [eax + HECKER_dv_frac]
    mov [esp + 8], ecx
    mov ecx, [eax + HECKER_count]
    mov [esp + 12], ecx
    mov edi, [eax + HECKER_dst]
    mov esi, [eax + HECKER_texel]
    mov edx, [eax + HECKER_v_frac]
    mov ebx, [eax + HECKER_du_frac]
    mov ecx, [eax + HECKER_u_frac]
    cmp dword [esp + 12], 0
    jle .done
.pixel:
    mov al, [esi]
    mov [edi], al
    inc edi
    add edx, [esp + 8]                  ; v fraction; CF = v carry
    sbb ebp, ebp                        ; 0, or -1 when v carried
    add ecx, ebx                        ; u fraction; CF = u carry
    adc esi, [esp + 4 + ebp * 4]        ; the table entry for the v carry, plus the u carry
    dec dword [esp + 12]
    jnz .pixel
.done:
    LOOP_LEAVE 16
